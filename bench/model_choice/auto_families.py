"""Seeded random problems with exact answers for validating `model: auto` (docs/model-choice-validation.md,
"Problems nobody tuned").

Each family draws an instance from a random.Random: a scene file (docs/scenes.md) and `exact(t)`, the positions the
exact solution of the rigid, undamped-by-the-engine problem gives its moving bodies at time t, as
{body index in the file: (x, y, z)}. Every input is rounded to a float first (`f32`), so the exact answer is the
answer of the very numbers the engine reads. Bodies keep all their velocity (`velocityRetention` 1) and volumes
have no velocity threshold (`velocityEpsilon` 0), as the reference problems (scenes/reference/); contact problems
have restitution 0 unless they are about a bounce. Standard library only."""
import math
import struct

G = 9.82  # m/s^2, the engine's gravity (docs/scenes.md)


def f32(x):
    """x rounded to the nearest float (what the scene loader stores)."""
    return struct.unpack("f", struct.pack("f", x))[0]


def log_uniform(rng, lo, hi):
    return math.exp(rng.uniform(math.log(lo), math.log(hi)))


def particle(pos, vel=(0, 0, 0), mass=1.0, **extra):
    body = {"type": "particle", "position": list(pos), "velocity": list(vel), "mass": mass, "velocityRetention": 1}
    body.update(extra)
    return body


def volume(kind, pos, mass=1.0, **extra):
    body = {"type": kind, "position": list(pos), "mass": mass, "velocityRetention": 1, "velocityEpsilon": 0}
    body.update(extra)
    return body


def ground(half, mu, top=0.0):
    """A static slab whose top face is y = top."""
    return volume("box", (0, top - 0.5, 0), 0, halfExtents=[half, 0.5, half], friction=mu, restitution=0)


def scene(name, duration, bodies, gravity=-G, **extra):
    for i, body in enumerate(bodies):
        body["id"] = f"b{i}"
    s = {"format": 1, "name": name, "duration": duration, "world": {"gravity": [0, gravity, 0]}, "bodies": bodies}
    s.update(extra)
    return s


def add(a, b, s=1.0):
    return tuple(x + s * y for x, y in zip(a, b))


def ballistic(p0, v0, t, g=G):
    return (p0[0] + v0[0] * t, p0[1] + v0[1] * t - 0.5 * g * t * t, p0[2] + v0[2] * t)


def horizontal_direction(rng):
    a = rng.uniform(0, 2 * math.pi)
    return (math.cos(a), 0.0, math.sin(a))


# ---------------------------------------------------------------------------------------------------------------
# Linear systems: the exact flow of z' = A z through exp(A t) (scaling and squaring of a Taylor series).


def mat_mul(a, b):
    n, m = len(a), len(b[0])
    bt = list(zip(*b))
    return [[sum(x * y for x, y in zip(a[i], bt[j])) for j in range(m)] for i in range(n)]


def expm(a):
    """exp(a) of a small square matrix, to double rounding (Taylor to 24 terms after scaling |a| below 1/2)."""
    n = len(a)
    norm = max(sum(abs(x) for x in row) for row in a)
    squarings = max(0, int(math.ceil(math.log2(norm / 0.5)))) if norm > 0.5 else 0
    scaled = [[x / 2**squarings for x in row] for row in a]
    result = [[float(i == j) for j in range(n)] for i in range(n)]
    term = [row[:] for row in result]
    for k in range(1, 25):
        term = [[x / k for x in row] for row in mat_mul(term, scaled)]
        result = [[x + y for x, y in zip(r, t)] for r, t in zip(result, term)]
    for _ in range(squarings):
        result = mat_mul(result, result)
    return result


def chain_matrix(masses, ks, bs, rests, g):
    """z' = A z for a vertical chain hanging from a fixed anchor at depth 0: z = (u_1..u_n, u_1'..u_n', 1), u the
    depth below the anchor (m, down positive). Spring i joins node i-1 (node 0 the anchor) to node i with tension
    k_i (l_i - L_i) + b_i l_i', l_i = u_i - u_{i-1} (the engine's spring: Hooke plus damping on the separation
    rate, docs/book-reference.md §3.6, erratum 5.2-20), linear while every l_i > 0."""
    n = len(masses)
    a = [[0.0] * (2 * n + 1) for _ in range(2 * n + 1)]
    for i in range(n):
        a[i][n + i] = 1.0
    for i in range(n):
        row = a[n + i]
        row[2 * n] += g
        # Tension of spring i (above bob i) pulls bob i up; of spring i+1 (below) pulls it down.
        for spring, sign in ((i, -1.0), (i + 1, 1.0)):
            if spring >= n:
                continue
            k, b, rest = ks[spring], bs[spring], rests[spring]
            lower, upper = spring, spring - 1  # l = u_lower - u_upper
            row[lower] += sign * k / masses[i]
            row[n + lower] += sign * b / masses[i]
            if upper >= 0:
                row[upper] -= sign * k / masses[i]
                row[n + upper] -= sign * b / masses[i]
            row[2 * n] -= sign * k * rest / masses[i]
    return a


def chain_state(a, z0, t):
    e = expm([[x * t for x in row] for row in a])
    return [sum(x * y for x, y in zip(row, z0)) for row in e]


# ---------------------------------------------------------------------------------------------------------------
# The pendulum: exact through Jacobi's elliptic sn (arithmetic-geometric mean, descending Landen).


def elliptic_k(m):
    a, b = 1.0, math.sqrt(1.0 - m)
    while abs(a - b) > 1e-15 * a:
        a, b = 0.5 * (a + b), math.sqrt(a * b)
    return math.pi / (2.0 * a)


def jacobi_sn(u, m):
    """sn(u | m), 0 <= m < 1: the arithmetic-geometric mean of 1 and sqrt(1 - m), then back down by
    phi_{n-1} = (phi_n + asin(c_n / a_n sin phi_n)) / 2 from phi_N = 2^N a_N u; sn = sin(phi_0)."""
    if m < 1e-300:
        return math.sin(u)
    a, b, cs = [1.0], math.sqrt(1.0 - m), [math.sqrt(m)]
    while abs(cs[-1]) > 1e-16 and len(a) < 40:
        an, bn, cn = 0.5 * (a[-1] + b), math.sqrt(a[-1] * b), 0.5 * (a[-1] - b)
        a.append(an)
        cs.append(cn)
        b = bn
    phi = 2 ** (len(a) - 1) * a[-1] * u
    for n in range(len(a) - 1, 0, -1):
        phi = 0.5 * (phi + math.asin(cs[n] / a[n] * math.sin(phi)))
    return math.sin(phi)


def pendulum_angle(theta0, omega0, t):
    """The angle (rad) of an ideal pendulum released from rest at theta0, omega0 = sqrt(g / L):
    theta = 2 asin(k sn(K - omega0 t | k^2)), k = sin(theta0 / 2)."""
    k = math.sin(0.5 * theta0)
    m = k * k
    return 2.0 * math.asin(max(-1.0, min(1.0, k * jacobi_sn(elliptic_k(m) - omega0 * t, m))))


# ---------------------------------------------------------------------------------------------------------------
# The families. Each draw returns (scene, exact, parameters): exact(t) -> {body index: (x, y, z)}.


def draw_projectile(rng):
    speed, elevation = f32(rng.uniform(3, 25)), math.radians(rng.uniform(5, 85))
    d = horizontal_direction(rng)
    v0 = tuple(f32(x) for x in (speed * math.cos(elevation) * d[0], speed * math.sin(elevation),
                                speed * math.cos(elevation) * d[2]))
    p0 = (0.0, f32(rng.uniform(0, 5)), 0.0)
    duration = f32(rng.uniform(0.5, 4))
    s = scene("projectile", duration, [particle(p0, v0)])
    return s, lambda t: {0: ballistic(p0, v0, t)}, {"speed": speed, "elevation_deg": math.degrees(elevation)}


def draw_free_fall(rng):
    """A particle or a sphere (a world of one volume) from rest."""
    kind = rng.choice(["particle", "sphere"])
    p0 = (0.0, f32(rng.uniform(0, 20)), 0.0)
    duration = f32(rng.uniform(0.3, 3))
    body = particle(p0) if kind == "particle" else volume("sphere", p0, radius=f32(rng.uniform(0.1, 1)))
    s = scene("free fall", duration, [body])
    return s, lambda t: {0: ballistic(p0, (0, 0, 0), t)}, {"body": kind}


def draw_spring(rng):
    """An anchor (mass 0) and a bob on one spring, hanging under gravity or in a random direction without it;
    damping ratio 0 (a third of the draws) or log-uniform 0.01..0.5; released from rest off its equilibrium."""
    k, m = f32(log_uniform(rng, 5, 500)), f32(log_uniform(rng, 0.1, 5))
    zeta = 0.0 if rng.random() < 1 / 3 else log_uniform(rng, 0.01, 0.5)
    b = f32(2 * zeta * math.sqrt(k * m))
    rest = f32(rng.uniform(0.5, 2))
    hanging = rng.random() < 0.5
    if hanging:
        direction, g = (0.0, -1.0, 0.0), G
    else:
        a, e = rng.uniform(0, 2 * math.pi), rng.uniform(-1, 1)
        direction, g = (math.cos(a) * math.sqrt(1 - e * e), e, math.sin(a) * math.sqrt(1 - e * e)), 0.0
    amplitude = rng.uniform(0.05, 0.4) * rest * rng.choice([-1, 1])
    length0 = rest + m * g / k + amplitude
    p0 = tuple(f32(length0 * x) for x in direction)
    length0 = math.sqrt(sum(x * x for x in p0))  # what the engine reads
    axis = tuple(x / length0 for x in p0)
    duration = f32(min(rng.uniform(1, 10), 8 * 2 * math.pi * math.sqrt(m / k) + 1))
    system = chain_matrix([m], [k], [b], [rest], g)  # along the axis: depth = distance from the anchor
    s = scene("spring", duration, [particle((0, 0, 0), mass=0), particle(p0, mass=m)], gravity=-g,
              springs=[{"a": "b0", "b": "b1", "stiffness": k, "damping": b, "restLength": rest}])

    def exact(t):
        u = chain_state(system, [length0, 0.0, 1.0], t)[0]
        return {1: tuple(u * x for x in axis)}

    return s, exact, {"k": k, "m": m, "zeta": zeta, "hanging": hanging}


def draw_chain(rng):
    """n = 2..4 bobs on springs hanging in a vertical line from an anchor, each bob moved off its equilibrium."""
    n = rng.randint(2, 4)
    masses = [f32(log_uniform(rng, 0.2, 3)) for _ in range(n)]
    ks = [f32(log_uniform(rng, 20, 400)) for _ in range(n)]
    zetas = [0.0 if rng.random() < 1 / 3 else log_uniform(rng, 0.01, 0.2) for _ in range(n)]
    bs = [f32(2 * z * math.sqrt(k * m)) for z, k, m in zip(zetas, ks, masses)]
    rests = [f32(rng.uniform(0.4, 1.2)) for _ in range(n)]
    # Equilibrium: spring i carries the weight of bobs i..n-1.
    depth, depths = 0.0, []
    for i in range(n):
        depth += rests[i] + sum(masses[i:]) * G / ks[i]
        depths.append(depth)
    while True:
        start = [f32(d + rng.uniform(-0.15, 0.15) * min(rests)) for d in depths]
        if all(b > a for a, b in zip([0.0] + start, start)):
            break
    system = chain_matrix(masses, ks, bs, rests, G)
    z0 = start + [0.0] * n + [1.0]
    duration = f32(rng.uniform(1, 6))
    # The exact motion is linear only while every spring keeps a positive length; check it on a fine grid.
    step = expm([[x * duration / 400 for x in row] for row in system])
    z = z0[:]
    for _ in range(400):
        z = [sum(x * y for x, y in zip(row, z)) for row in step]
        if any(b - a <= 0.01 for a, b in zip([0.0] + z[:n], z[:n])):
            return draw_chain(rng)
    bodies = [particle((0, 0, 0), mass=0)] + [particle((0, -u, 0), mass=m) for u, m in zip(start, masses)]
    springs = [{"a": f"b{i}", "b": f"b{i + 1}", "stiffness": ks[i], "damping": bs[i], "restLength": rests[i]}
               for i in range(n)]
    s = scene(f"chain of {n} springs", duration, bodies, springs=springs)

    def exact(t):
        u = chain_state(system, z0, t)
        return {i + 1: (0.0, -u[i], 0.0) for i in range(n)}

    return s, exact, {"n": n}


def draw_pendulum(rng):
    """A bob on a distance joint to a pivot of mass 0, released from rest at 5..150 degrees."""
    length = f32(rng.uniform(0.3, 3))
    theta0 = math.radians(rng.uniform(5, 150))
    pivot = (0.0, f32(rng.uniform(0, 4)), 0.0)
    bob = (f32(length * math.sin(theta0)), f32(pivot[1] - length * math.cos(theta0)), 0.0)
    theta0 = math.atan2(bob[0], pivot[1] - bob[1])  # the angle of the float positions
    omega0 = math.sqrt(G / length)
    duration = f32(rng.uniform(1, 8))
    s = scene("pendulum", duration, [particle(pivot, mass=0), particle(bob)],
              joints=[{"a": "b0", "b": "b1", "length": length}])

    def exact(t):
        th = pendulum_angle(theta0, omega0, t)
        return {1: (length * math.sin(th), pivot[1] - length * math.cos(th), 0.0)}

    return s, exact, {"length": length, "theta0_deg": math.degrees(theta0)}


def bounce_position(h, vx, e, t):
    """(x, y) of a point dropped from height h with horizontal speed vx onto y = 0, bouncing with restitution e."""
    t_hit, v_up = math.sqrt(2 * h / G), None
    if t <= t_hit:
        return vx * t, h - 0.5 * G * t * t
    v_up, t0 = e * G * t_hit, t_hit
    while v_up > 1e-9:
        flight = 2 * v_up / G
        if t <= t0 + flight:
            tau = t - t0
            return vx * t, v_up * tau - 0.5 * G * tau * tau
        t0, v_up = t0 + flight, e * v_up
    return vx * t, 0.0


def draw_bounce(rng):
    """A particle dropped onto a static OBB (a scene constraint) with restitution 0.3..0.9, ending before its fourth
    impact. The exact answer is the ideal bounce off the surface y = 0 (the engine puts a particle
    Particle::kContactOffset = 3 mm off the surface at each impact: part of its error here)."""
    e, h, vx = f32(rng.uniform(0.3, 0.9)), f32(rng.uniform(0.5, 5)), f32(rng.uniform(0, 2))
    t_hit = math.sqrt(2 * h / G)
    t_fourth = t_hit * (1 + 2 * e + 2 * e * e + 2 * e**3)
    duration = f32(rng.uniform(0.5 * t_hit, t_fourth))
    s = scene("particle bounce", duration, [particle((0, h, 0), (vx, 0, 0), restitution=e)],
              constraints=[{"position": [0, -1, 0], "halfExtents": [50, 1, 50]}])

    def exact(t):
        x, y = bounce_position(h, vx, e, t)
        return {0: (x, y, 0.0)}

    return s, exact, {"e": e, "h": h}


def draw_box_slide(rng):
    """A box sliding on flat ground to a stop: deceleration mu g, stop after v0 / (mu g)."""
    mu, v0 = f32(rng.uniform(0.2, 0.8)), f32(rng.uniform(0.5, 5))
    hx, hz = f32(rng.uniform(0.1, 0.5)), f32(rng.uniform(0.1, 0.5))
    hy = f32(rng.uniform(0.05, min(hx, hz)))  # mu hy < min(hx, hz): it slides without tipping
    d = horizontal_direction(rng)
    vel = (f32(v0 * d[0]), 0.0, f32(v0 * d[2]))
    v0 = math.hypot(vel[0], vel[2])
    t_stop = v0 / (mu * G)
    duration = f32(t_stop * rng.uniform(1.1, 2))
    p0 = (0.0, hy, 0.0)
    box = volume("box", p0, halfExtents=[hx, hy, hz], euler=[0, f32(rng.uniform(0, 90)), 0], velocity=list(vel),
                 friction=mu, restitution=0)
    s = scene("box sliding to a stop", duration, [ground(v0 * t_stop + 5, mu), box])

    def exact(t):
        tt = min(t, t_stop)
        travelled = (v0 * tt - 0.5 * mu * G * tt * tt) / v0
        return {1: (vel[0] * travelled, hy, vel[2] * travelled)}

    return s, exact, {"mu": mu, "v0": v0, "t_stop": t_stop}


def draw_incline(rng, kind):
    """A box or a sphere released from rest on a slab tilted 10..35 degrees about z. The box sticks when
    mu >= tan(theta), else slides at g (sin - mu cos); the sphere rolls without slipping at 5/7 g sin when
    mu >= 2/7 tan(theta), else slides at g (sin - mu cos)."""
    theta = math.radians(rng.uniform(10, 35))
    q = [0.0, 0.0, f32(math.sin(theta / 2)), f32(math.cos(theta / 2))]
    theta = 2 * math.atan2(q[2], q[3])
    limit = math.tan(theta) * (1.0 if kind == "box" else 2.0 / 7.0)
    sticks = rng.random() < 0.5
    mu = f32(limit * (rng.uniform(1.3, 2.5) if sticks else rng.uniform(0.1, 0.75)))
    if kind == "box" and sticks:
        accel = 0.0
    elif kind == "sphere" and sticks:
        accel = 5.0 / 7.0 * G * math.sin(theta)
    else:
        accel = G * (math.sin(theta) - mu * math.cos(theta))
    duration = f32(rng.uniform(0.5, 2.5))
    travel = 0.5 * accel * duration**2
    normal, uphill = (-math.sin(theta), math.cos(theta), 0.0), (math.cos(theta), math.sin(theta), 0.0)
    if kind == "box":
        hx, hz = f32(rng.uniform(0.1, 0.5)), f32(rng.uniform(0.1, 0.5))
        hy = f32(rng.uniform(0.05, hx))  # tan(35 deg) < hx / hy: it slides without tipping
        lift, extra = hy, {"halfExtents": [hx, hy, hz], "quaternion": q}
    else:
        r = f32(rng.uniform(0.1, 0.5))
        lift, extra = r, {"radius": r}
    half = travel + 3
    start = tuple(f32(x) for x in add(add((0, 0, 0), normal, 0.5 + lift), uphill, half - 1.5))
    slab = volume("box", (0, 0, 0), 0, halfExtents=[half, 0.5, 3], quaternion=q, friction=mu, restitution=0)
    body = volume(kind, start, friction=mu, restitution=0, **extra)
    s = scene(f"{kind} on an incline", duration, [slab, body])

    def exact(t):
        return {1: add(start, uphill, -0.5 * accel * t * t)}

    return s, exact, {"theta_deg": math.degrees(theta), "mu": mu, "regime": ("sticks" if kind == "box" else
                                                                         "rolls") if sticks else "slides"}


def draw_rolling(rng):
    """A sphere sent along flat ground without spin: it slides at -mu g until v = omega r, at 2 v0 / (7 mu g),
    then rolls at 5/7 v0."""
    mu, v0, r = f32(rng.uniform(0.1, 0.6)), f32(rng.uniform(0.5, 5)), f32(rng.uniform(0.1, 0.5))
    d = horizontal_direction(rng)
    vel = (f32(v0 * d[0]), 0.0, f32(v0 * d[2]))
    v0 = math.hypot(vel[0], vel[2])
    t_roll = 2 * v0 / (7 * mu * G)
    duration = f32(t_roll * rng.uniform(1.2, 3))
    s = scene("sphere sliding into rolling", duration,
              [ground(v0 * duration + 5, mu), volume("sphere", (0, r, 0), radius=r, velocity=list(vel), friction=mu,
                                                     restitution=0)])

    def exact(t):
        ts = min(t, t_roll)
        travelled = v0 * ts - 0.5 * mu * G * ts * ts + 5.0 / 7.0 * v0 * max(0.0, t - t_roll)
        return {1: (vel[0] / v0 * travelled, r, vel[2] / v0 * travelled)}

    return s, exact, {"mu": mu, "v0": v0, "t_roll": t_roll}


def draw_box_grid(rng):
    """n x n separate cubes (n = 2..5) dropped flat from a height onto the ground: they fall freely and stop."""
    n, half = rng.randint(2, 5), f32(rng.uniform(0.1, 0.3))
    drop = f32(rng.uniform(0.05, 1))
    spacing = f32(4 * half)
    t_hit = math.sqrt(2 * drop / G)
    duration = f32(t_hit + rng.uniform(0.3, 1.5))
    starts = [(f32((i - (n - 1) / 2) * spacing), f32(half + drop), f32((j - (n - 1) / 2) * spacing))
              for i in range(n) for j in range(n)]
    boxes = [volume("box", p, halfExtents=[half] * 3, friction=0.5, restitution=0) for p in starts]
    s = scene(f"{n} x {n} boxes dropped flat", duration, [ground(n * spacing + 2, 0.5)] + boxes)

    def exact(t):
        fall = 0.5 * G * min(t, t_hit) ** 2
        return {i + 1: (p[0], p[1] - fall, p[2]) for i, p in enumerate(starts)}

    return s, exact, {"n": n, "drop": drop}


def draw_slide_grid(rng):
    """3 x 3 or 4 x 4 boxes sliding to a stop on one ground, each at its own speed and heading, too far apart to
    meet: the box slide's exact answer for each. A costlier world (the validation's cost set)."""
    n, mu = rng.randint(3, 4), f32(rng.uniform(0.2, 0.8))
    spacing = f32(2 * 3.0**2 / (2 * mu * G) + 2)
    boxes, answers = [], []
    for i in range(n * n):
        hx, hz = f32(rng.uniform(0.1, 0.4)), f32(rng.uniform(0.1, 0.4))
        hy = f32(rng.uniform(0.05, min(hx, hz)))
        d, v0 = horizontal_direction(rng), rng.uniform(0.5, 3)
        vel = (f32(v0 * d[0]), 0.0, f32(v0 * d[2]))
        p0 = (f32((i // n - (n - 1) / 2) * spacing), hy, f32((i % n - (n - 1) / 2) * spacing))
        boxes.append(volume("box", p0, halfExtents=[hx, hy, hz], velocity=list(vel), friction=mu, restitution=0))
        answers.append((p0, vel, math.hypot(vel[0], vel[2])))
    t_stop = max(v / (mu * G) for _, _, v in answers)
    duration = f32(t_stop * rng.uniform(1.1, 1.5))
    s = scene(f"{n} x {n} boxes sliding to a stop", duration, [ground(n * spacing, mu)] + boxes)

    def exact(t):
        out = {}
        for i, (p0, vel, v0) in enumerate(answers):
            tt = min(t, v0 / (mu * G))
            travelled = (v0 * tt - 0.5 * mu * G * tt * tt) / v0
            out[i + 1] = (p0[0] + vel[0] * travelled, p0[1], p0[2] + vel[2] * travelled)
        return out

    return s, exact, {"n": n, "mu": mu, "t_stop": t_stop}


FAMILIES = {
    "projectile": draw_projectile,
    "free-fall": draw_free_fall,
    "spring": draw_spring,
    "chain": draw_chain,
    "pendulum": draw_pendulum,
    "bounce": draw_bounce,
    "box-slide": draw_box_slide,
    "incline-box": lambda rng: draw_incline(rng, "box"),
    "incline-sphere": lambda rng: draw_incline(rng, "sphere"),
    "rolling": draw_rolling,
    "box-grid": draw_box_grid,
    "slide-grid": draw_slide_grid,
}
# The validation's default set: every family but the costlier slide-grid, which is the cost set (--families).
DEFAULT_FAMILIES = [f for f in FAMILIES if f != "slide-grid"]

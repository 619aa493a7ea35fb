#include "Application/Render/FixedFunctionPrimitives.h"

#include <glad/gl.h>

#include "Application/View/Tessellation.h"

// Everything here is OpenGL 2.1 immediate mode on the current context. Colours of lit geometry come from
// GL_LIGHT0's ambient/diffuse (docs/book-reference.md §1.5); glColor only matters for the unlit debug drawing.

namespace {

void Emit(const TriangleList& list) {
    glBegin(GL_TRIANGLES);
    for (std::size_t i = 0; i < list.positions.size(); ++i) {
        glNormal3f(list.normals[i].x, list.normals[i].y, list.normals[i].z);
        glVertex3f(list.positions[i].x, list.positions[i].y, list.positions[i].z);
    }
    glEnd();
}

void Vertex(const vec3& v) { glVertex3f(v.x, v.y, v.z); }

/// Unit spheres by subdivision count, built once: drawing only scales positions (not normals).
const TriangleList& UnitSphere(int divisions) {
    static TriangleList cache[5];
    static bool built[5] = {};
    const int d = divisions < 0 ? 0 : (divisions > 4 ? 4 : divisions);
    if (!built[d]) {
        cache[d] = Icosphere(d, 1.0f);
        built[d] = true;
    }
    return cache[d];
}

}  // namespace

void Render(const Point& point) {
    glBegin(GL_POINTS);
    Vertex(point);
    glEnd();
}

void Render(const Line& line) {
    glBegin(GL_LINES);
    Vertex(line.start);
    Vertex(line.end);
    glEnd();
}

void Render(const Ray& ray) { Render(Line(ray.origin, ray.origin + ray.direction * 50000.0f)); }

void Render(const Sphere& sphere) {
    glPushMatrix();
    glTranslatef(sphere.position.x, sphere.position.y, sphere.position.z);
    FixedFunctionSphere(2, sphere.radius);
    glPopMatrix();
}

void Render(const AABB& aabb) {
    glPushMatrix();
    glTranslatef(aabb.position.x, aabb.position.y, aabb.position.z);
    FixedFunctionCube(aabb.size.x, aabb.size.y, aabb.size.z);
    glPopMatrix();
}

void Render(const OBB& obb) {
    // Row-vector world matrix (docs/book-reference.md §0); its row-major array is the column-major matrix GL expects.
    // The scale goes through the matrix, so face normals get length 1/size (no GL_NORMALIZE,
    // docs/book-reference.md §1.5).
    const mat4 world = Scale(obb.size) * FromMat3(obb.orientation) * Translation(obb.position);
    glPushMatrix();
    glMultMatrixf(world.asArray);
    FixedFunctionCube();
    glPopMatrix();
}

void Render(const Plane& plane) { Render(plane, 1.0f); }

void Render(const Plane& plane, float scale) {
    // Both windings and no glNormal, as the book: lit with whatever normal is current.
    const std::array<vec3, 4> q = PlaneQuad(plane, scale);
    glBegin(GL_TRIANGLES);
    Vertex(q[0]), Vertex(q[1]), Vertex(q[2]);
    Vertex(q[0]), Vertex(q[2]), Vertex(q[3]);
    Vertex(q[0]), Vertex(q[2]), Vertex(q[1]);
    Vertex(q[0]), Vertex(q[3]), Vertex(q[2]);
    glEnd();

    // Black unit normal line from the centre.
    const vec3 centre = plane.normal * plane.distance;
    glPushAttrib(GL_ENABLE_BIT | GL_CURRENT_BIT);
    glDisable(GL_LIGHTING);
    glColor3f(0.0f, 0.0f, 0.0f);
    Render(Line(centre, centre + plane.normal));
    glPopAttrib();
}

void Render(const Triangle& triangle) { Render(triangle, false); }

void Render(const Triangle& triangle, bool oneSided) {
    glBegin(GL_TRIANGLES);
    if (oneSided) {
        const vec3 n = FrontNormal(triangle.a, triangle.b, triangle.c);
        glNormal3f(n.x, n.y, n.z);
        Vertex(triangle.a), Vertex(triangle.b), Vertex(triangle.c);
    } else {
        Vertex(triangle.a), Vertex(triangle.c), Vertex(triangle.b);
        Vertex(triangle.a), Vertex(triangle.b), Vertex(triangle.c);
    }
    glEnd();
}

void Render(const CollisionManifold& manifold) {
    if (!manifold.colliding) return;
    glPushAttrib(GL_ENABLE_BIT | GL_CURRENT_BIT);
    glDisable(GL_LIGHTING);

    glColor3f(1.0f, 0.0f, 0.0f);
    glBegin(GL_POINTS);
    for (const vec3& c : manifold.contacts) Vertex(c);
    glEnd();

    glColor3f(0.0f, 1.0f, 0.0f);
    glBegin(GL_LINES);
    for (const vec3& c : manifold.contacts) {
        Vertex(c);
        Vertex(c + manifold.normal * manifold.depth);
    }
    glEnd();

    if (!manifold.contacts.empty()) {
        vec3 centroid;
        for (const vec3& c : manifold.contacts) centroid += c;
        centroid = centroid * (1.0f / static_cast<float>(manifold.contacts.size()));
        glColor3f(0.0f, 0.0f, 1.0f);
        Render(Line(centroid, centroid + manifold.normal));
    }
    glPopAttrib();
}

void Render(const std::vector<Line>& edges) {
    glBegin(GL_LINES);
    for (const Line& l : edges) Vertex(l.start), Vertex(l.end);
    glEnd();
}

void Render(const std::array<Line, 12>& edges) {
    glBegin(GL_LINES);
    for (const Line& l : edges) Vertex(l.start), Vertex(l.end);
    glEnd();
}

void Render(const Mesh& mesh) {
    // OBJ files are usually wound CCW in a right-handed frame, the opposite of our front faces, and a
    // hand-made asset may be either way round: draw both sides with the flat normal of each triangle taken
    // as normalize((b - a) x (c - a)) (outward for a right-handed CCW file).
    glPushAttrib(GL_ENABLE_BIT);
    glDisable(GL_CULL_FACE);
    glBegin(GL_TRIANGLES);
    for (const Triangle& t : mesh.triangles) {
        const vec3 n = Normalized(Cross(t.b - t.a, t.c - t.a));
        glNormal3f(n.x, n.y, n.z);
        Vertex(t.a), Vertex(t.b), Vertex(t.c);
    }
    glEnd();
    glPopAttrib();
}

void Render(const Model& model) {
    if (model.content == nullptr) return;
    const mat4 world = GetWorldMatrix(model);
    glPushMatrix();
    glMultMatrixf(world.asArray);
    Render(*model.content);
    glPopMatrix();
}

void FixedFunctionSphere(int divisions, float radius) {
    const TriangleList& unit = UnitSphere(divisions);
    glBegin(GL_TRIANGLES);
    for (std::size_t i = 0; i < unit.positions.size(); ++i) {
        const vec3& n = unit.normals[i];
        glNormal3f(n.x, n.y, n.z);
        Vertex(unit.positions[i] * radius);
    }
    glEnd();
}

void FixedFunctionCube(float extentsX, float extentsY, float extentsZ) { Emit(Cube(extentsX, extentsY, extentsZ)); }

void FixedFunctionOrigin(bool depthTest, bool twoSided) {
    glPushAttrib(GL_ENABLE_BIT);
    glDisable(GL_LIGHTING);
    if (depthTest)
        glEnable(GL_DEPTH_TEST);
    else
        glDisable(GL_DEPTH_TEST);
    // twoSided also draws the negative half axes, in the same colours.
    const float back = twoSided ? -1.0f : 0.0f;
    glBegin(GL_LINES);
    glColor3f(1.0f, 0.0f, 0.0f);
    glVertex3f(back, 0.0f, 0.0f), glVertex3f(1.0f, 0.0f, 0.0f);
    glColor3f(0.0f, 1.0f, 0.0f);
    glVertex3f(0.0f, back, 0.0f), glVertex3f(0.0f, 1.0f, 0.0f);
    glColor3f(0.0f, 0.0f, 1.0f);
    glVertex3f(0.0f, 0.0f, back), glVertex3f(0.0f, 0.0f, 1.0f);
    glEnd();
    glPopAttrib();  // the current colour stays blue, as in the book
}

void SetLightColors(const vec3& ambient, const vec3& diffuse) {
    const GLfloat a[4] = {ambient.x, ambient.y, ambient.z, 0.0f};
    const GLfloat d[4] = {diffuse.x, diffuse.y, diffuse.z, 0.0f};
    const GLfloat zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_AMBIENT, a);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, d);
    glLightfv(GL_LIGHT0, GL_SPECULAR, zero);
}

void SetLightDirection(const vec3& direction) {
    const GLfloat p[4] = {direction.x, direction.y, direction.z, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, p);
}

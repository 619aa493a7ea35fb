#!/bin/sh
# Smoke test of psb-peer-bench (docs/peers.md) on small scenes: one line with every key, finite positive times,
# what the physics must show in both engines, and bad usage refused with exit 2 and the bad value named. No
# timing assertions (the machine may be busy). Usage: peer_bench_test.sh PATH/TO/psb-peer-bench
set -eu
bench=$1
fail() { echo "peers.smoke: FAIL: $*" >&2; exit 1; }
out=$(mktemp) err=$(mktemp) dir=$(mktemp -d)
trap 'rm -f "$out" "$err"; rm -rf "$dir"' EXIT

# value KEY: the value of KEY in the line in $out (empty if absent).
value() { tr ' ' '\n' <"$out" | awk -F= -v k="$1" '$1 == k { print $2 }'; }
# check_keys KEY...: each key present exactly once with a non-empty value.
check_keys() {
  for k in "$@"; do
    [ "$(tr ' ' '\n' <"$out" | grep -c "^$k=.")" -eq 1 ] || fail "key '$k' missing or repeated in: $(cat "$out")"
  done
}
# holds EXPR: an awk condition over the line's keys (as variables) that must be true.
holds() {
  tr ' ' '\n' <"$out" | awk -F= -v what="$1" '{ v[$1] = $2 }
    END {
      split(what, t, " ")
      # t[1] key, t[2] operator, t[3] number
      x = v[t[1]]
      if (x == "" || x ~ /nan|inf/) exit 1
      if (t[2] == "<") exit !(x + 0 < t[3] + 0)
      if (t[2] == ">") exit !(x + 0 > t[3] + 0)
      if (t[2] == "==") exit !(x + 0 == t[3] + 0)
      exit 1
    }' || fail "expected $1 in: $(cat "$out")"
}
common="scene n solver sleep bullet_ms psb_ms ratio bullet_cpu_ms psb_cpu_ms cpu_ratio bullet_pen psb_pen steps warmup repeat"

# --- help and bad usage
"$bench" --help >"$out" || fail "--help exited $?"
grep -q "^Usage: psb-peer-bench SCENE N" "$out" || fail "--help prints no usage"
refused() {  # refused NEEDLE ARGS...: exit 2 and NEEDLE on stderr
  needle=$1
  shift
  set +e
  "$bench" "$@" >"$out" 2>"$err"
  code=$?
  set -e
  [ "$code" -eq 2 ] || fail "'$*' exited $code, expected 2"
  grep -q -- "$needle" "$err" || fail "'$*': stderr does not name '$needle': $(cat "$err")"
  [ ! -s "$out" ] || fail "'$*' printed a result line"
}
refused "expected SCENE N"
refused "'spiral'" spiral 5
refused "'0'" tower 0
refused "'five'" tower five
refused "'200000'" boxpile 200000
refused "'nope'" tower 5 --solver nope
refused "'--frobnicate'" tower 5 --frobnicate 1
refused "--warmup 10 must be smaller than --steps 10" tower 5 --steps 10 --warmup 10
refused "'0'" tower 5 --repeat 0
refused "'-3'" tower 5 --steps -3
refused "missing value after '--steps'" tower 5 --steps
refused "'$dir/none/x.csv'" tower 5 --csv "$dir/none/x.csv"
[ -z "$(ls "$dir")" ] || fail "a refused --csv left files behind: $(ls "$dir")"

# --- tower 5, accumulated: stands in both engines
"$bench" tower 5 --solver accumulated --steps 120 --warmup 10 --repeat 1 >"$out" 2>"$err" || fail "tower 5 exited $?"
[ "$(wc -l <"$out")" -eq 1 ] || fail "tower 5 printed $(wc -l <"$out") lines"
check_keys $common bullet_disp psb_disp bullet_drift psb_drift
[ "$(value scene)" = tower ] && [ "$(value n)" = 5 ] && [ "$(value solver)" = accumulated ] ||
  fail "scene, n or solver not echoed: $(cat "$out")"
for k in bullet_ms psb_ms ratio bullet_cpu_ms psb_cpu_ms cpu_ratio; do
  holds "$k > 0"
done
for e in bullet psb; do
  holds "${e}_disp < 0.05"
  holds "${e}_drift < 0.05"
  holds "${e}_pen < 0.05"
done

# --- boxpile 100: nothing falls through the ground; the pile is not exploding
"$bench" boxpile 100 --solver accumulated --steps 120 --warmup 10 --repeat 1 >"$out" 2>"$err" ||
  fail "boxpile 100 exited $?"
check_keys $common bullet_ke psb_ke bullet_below psb_below
holds "bullet_ms > 0"
holds "psb_ms > 0"
for e in bullet psb; do
  holds "${e}_below == 0"
  holds "${e}_pen < 0.5"
  holds "${e}_ke < 1000"
done

# --- pyramid 4 with the book's solver, two rounds: the keys of a pyramid
"$bench" pyramid 4 --solver book --steps 30 --warmup 5 --repeat 2 >"$out" 2>"$err" || fail "pyramid 4 exited $?"
check_keys $common bullet_disp psb_disp
[ "$(value solver)" = book ] && [ "$(value repeat)" = 2 ] || fail "solver or repeat not echoed: $(cat "$out")"
holds "bullet_ms > 0"
holds "psb_ms > 0"
holds "bullet_disp < 1"
holds "psb_disp < 1"

# --- tower 5 and boxpile 100 with the soft step (the solver of the README's table): it stands, settles shallow
"$bench" tower 5 --solver soft --steps 120 --warmup 10 --repeat 1 >"$out" 2>"$err" || fail "soft tower 5 exited $?"
[ "$(value solver)" = soft ] || fail "solver not echoed: $(cat "$out")"
holds "psb_disp < 0.05"
holds "psb_drift < 0.05"
holds "psb_pen < 0.01"
"$bench" boxpile 100 --solver soft --steps 120 --warmup 10 --repeat 1 >"$out" 2>"$err" ||
  fail "soft boxpile 100 exited $?"
holds "psb_below == 0"
holds "psb_pen < 0.05"
holds "psb_ke < 10"
# --- --sleep and --csv: both engines sleep; one CSV row per engine, with the header a docs generator reads
"$bench" tower 5 --solver soft --sleep --steps 200 --warmup 10 --repeat 1 --csv "$dir/t.csv" >"$out" 2>"$err" ||
  fail "tower 5 --sleep --csv exited $?"
[ "$(value sleep)" = on ] || fail "sleep not echoed as on: $(cat "$out")"
holds "psb_disp < 0.05"
[ "$(ls "$dir")" = t.csv ] || fail "--csv left other files: $(ls "$dir")"
[ "$(sed -n 1p "$dir/t.csv")" = "scene,bodies,sleep,threads,engine,cpu_ms_per_step,ratio_to_bullet,max_displacement_m,stands" ] ||
  fail "CSV header: $(sed -n 1p "$dir/t.csv")"
[ "$(wc -l <"$dir/t.csv")" -eq 3 ] || fail "CSV has $(wc -l <"$dir/t.csv") lines, expected 3"
awk -F, 'NR == 2 && !($1 == "tower" && $2 == 5 && $3 == "on" && $4 == 1 && $5 == "psb-soft" && $6 > 0 && $7 > 0 && $9 == "yes") { exit 1 }
         NR == 3 && !($5 == "bullet" && $7 == 1) { exit 1 }' "$dir/t.csv" || fail "CSV rows: $(cat "$dir/t.csv")"
cpu=$(tr ' ' '\n' <"$out" | awk -F= '$1 == "psb_cpu_ms" { print $2 }')
awk -F, -v c="$cpu" 'NR == 2 { exit !($6 + 0 > 0.999 * c && $6 + 0 < 1.001 * c) }' "$dir/t.csv" ||
  fail "CSV psb time $(sed -n 2p "$dir/t.csv") is not the line's psb_cpu_ms=$cpu"
"$bench" tower 5 --solver soft --steps 30 --warmup 5 --repeat 1 --csv "$dir/t.csv" >"$out" 2>"$err" || fail "second --csv run"
[ "$(value sleep)" = off ] || fail "sleep not echoed as off: $(cat "$out")"
[ "$(awk -F, 'NR == 2 { print $3 }' "$dir/t.csv")" = off ] || fail "CSV not replaced: $(cat "$dir/t.csv")"
# --- --trace: a header and one row per step of each engine's run; the soft tower falls asleep in both engines
"$bench" tower 5 --solver soft --sleep --steps 200 --warmup 10 --repeat 1 --trace "$dir/trace.csv" >"$out" 2>"$err" ||
  fail "--trace exited $?"
[ "$(sed -n 1p "$dir/trace.csv")" = "engine,round,step,cpu_us,awake" ] || fail "trace header: $(sed -n 1p "$dir/trace.csv")"
[ "$(wc -l <"$dir/trace.csv")" -eq 401 ] || fail "trace has $(wc -l <"$dir/trace.csv") lines, expected 401"
for e in bullet psb; do
  awk -F, -v e="$e" '$1 == e && $3 == 0 && $5 != 5 { exit 1 } $1 == e && $3 == 199 { last = $5 } END { exit last != 0 }' \
    "$dir/trace.csv" || fail "$e: not 5 awake at step 0 and 0 at step 199 in the trace"
done
refused "'$dir/none/t.csv'" tower 5 --trace "$dir/none/t.csv"
echo "peers.smoke: ok"

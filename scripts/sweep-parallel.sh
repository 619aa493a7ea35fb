#!/usr/bin/env bash
# Runs the speed-accuracy sweep as N shards through GNU parallel (Debian's `parallel`), on this machine's cores
# or on the hosts of an --sshloginfile, and merges the shards into one CSV (scripts/sweep-merge.sh).
#
#   scripts/sweep-parallel.sh --out results.csv                                  # N = jobs = local cores
#   scripts/sweep-parallel.sh --jobs 2 --out q.csv -- --quick                    # psb-sweep arguments after --
#   scripts/sweep-parallel.sh --shards 16 --sshloginfile hosts --sweep /shared/build/psb-sweep --out r.csv
#
# Each shard is `psb-sweep ARGS --shard I/N` writing its CSV to standard output; parallel brings that output
# back whole lines at a time (also from ssh hosts, where --sweep must name a psb-sweep built from the same
# commit), and the shards' progress lines reach stderr as they come. Shards are
# dealt by estimated cost inside psb-sweep, so N shards take about equally long. Exit 2 on bad usage; 1 if a
# shard fails (the others are stopped and nothing is written).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
usage() {
  sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'
  echo "options: --out FILE (required) --jobs N --shards N --sshloginfile FILE --sweep PATH [-- psb-sweep args]"
}
out= jobs= shards= login= sweep=$root/build/psb-sweep
while [ $# -gt 0 ]; do
  case $1 in
    --out) out=${2:?--out needs a file}; shift 2 ;;
    --jobs) jobs=${2:?--jobs needs a number}; shift 2 ;;
    --shards) shards=${2:?--shards needs a number}; shift 2 ;;
    --sshloginfile) login=${2:?--sshloginfile needs a file}; shift 2 ;;
    --sweep) sweep=${2:?--sweep needs a path}; shift 2 ;;
    --help|-h) usage; exit 0 ;;
    --) shift; break ;;
    *) echo "sweep-parallel: unknown argument '$1'" >&2; usage >&2; exit 2 ;;
  esac
done
command -v parallel >/dev/null || { echo "sweep-parallel: GNU parallel not found (Debian package 'parallel')" >&2; exit 2; }
[ -n "$out" ] || { echo "sweep-parallel: --out FILE is required" >&2; exit 2; }
for n in "$jobs" "$shards"; do
  [ -z "$n" ] || [[ $n =~ ^[1-9][0-9]{0,4}$ ]] || { echo "sweep-parallel: '$n' is not a whole number 1..99999" >&2; exit 2; }
done
[ -z "$login" ] || [ -f "$login" ] || { echo "sweep-parallel: no sshloginfile '$login'" >&2; exit 2; }
[ -n "$login" ] || [ -x "$sweep" ] || { echo "sweep-parallel: no psb-sweep at '$sweep' (build it, or pass --sweep)" >&2; exit 2; }
jobs=${jobs:-$(nproc 2>/dev/null || echo 2)}
shards=${shards:-$jobs}
outdir=$(dirname -- "$out")
[ -d "$outdir" ] || { echo "sweep-parallel: directory '$outdir' of --out does not exist" >&2; exit 2; }

work=$(mktemp -d "$outdir/.sweep-parallel.XXXXXX")
trap 'rm -rf "$work"' EXIT
# One shard's command, quoted for the (possibly remote) shell.
cmd=$(printf '%q ' "$sweep" "$@")
where=(--jobs "$jobs")
[ -z "$login" ] || where=(--sshloginfile "$login" --jobs "$jobs")
echo "sweep-parallel: $shards shards, $jobs at a time${login:+ on the hosts of $login}" >&2
seq 1 "$shards" | parallel "${where[@]}" --halt now,fail=1 --line-buffer "$cmd --shard {}/$shards" >"$work/shards.csv" ||
  { echo "sweep-parallel: a shard failed; nothing written" >&2; exit 1; }
bash "$root/scripts/sweep-merge.sh" "$out" "$work/shards.csv"
# Date, machine and commit of the measurement beside the CSV (OUT.meta), for docs/results.md (scripts/gen-results.py).
python3 "$root/scripts/gen-results.py" --stamp "$out" --command "scripts/sweep-parallel.sh --jobs $jobs${login:+ --sshloginfile $login} --out $(basename -- "$out")" ||
  echo "sweep-parallel: could not write $out.meta" >&2

#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Pair freedoms on the distributed backend (`--pair BODY1:BODY2`, `--coupled-pairs`) at P = 1
# and P = 2 against the serial sparse path (`analyze --sparse`, network::sparse_pair_freedoms on
# generic vectors from the sparse QR, itself tested against Davies' dense method), on an example
# and on a generated ladder; and against values derived by hand for the parallelogram with a
# redundant crank (examples/parallelogram-redundant.yaml, d = 3): the three cranks are parallel,
# equal links, so the coupler translates (FN = 1) and every revolute turns in that motion
# (fij = 1 for each coupling's pair: f = 1, c = 2); ground and coupler, not coupled directly,
# have fij = 1 (the translation). The one self-stress is the cranks' axial forces along three
# parallel lines through x = 0, 6 and 3 on the ground: f1 + f2 + f3 = 0 and 6 f2 + 3 f3 = 0 give
# f1 = f2 = -f3 / 2, all nonzero, so every revolute carries it: cij = 1 for each coupling.
# Usage: check_pairs.sh MPIRUN KINESTAT SOURCE_DIR WORK_DIR
set -eu
mpirun=$1 kinestat=$2 source=$3 work=$4
mkdir -p "$work"
example=$source/examples/parallelogram-redundant.yaml
ladder=$work/ladder-500.yaml
/usr/bin/python3 "$source/bench/ladder_network.py" 500 > "$ladder"
check() {  # check NAME MODEL PAIR-OPTIONS...
  name=$1 model=$2
  shift 2
  "$kinestat" analyze "$model" --sparse --json "$@" > "$work/$name-serial.json"
  for p in 1 2; do
    "$mpirun" -n "$p" "$kinestat" analyze --backend petsc "$model" --json "$@" > "$work/$name-petsc-$p.json"
    /usr/bin/python3 - "$work/$name-serial.json" "$work/$name-petsc-$p.json" "$name" "$p" <<'PY'
import json, sys
serial, petsc = (json.load(open(p)) for p in sys.argv[1:3])
name, p = sys.argv[3], sys.argv[4]
assert petsc["method"] == "petsc_mumps" and petsc["backend"]["processes"] == int(p), (petsc["method"], petsc["backend"])
assert serial["pairs"] == petsc["pairs"], [(a, b) for a, b in zip(serial["pairs"], petsc["pairs"]) if a != b][:5]
assert serial["not_computed"] == petsc["not_computed"], (serial["not_computed"], petsc["not_computed"])
rows = petsc["pairs"]
print(f"{name} P = {p}: {len(rows)} pairs as the serial sparse path's; fij > 0 in {sum(r['fij'] > 0 for r in rows)}, "
      f"cij > 0 in {sum(r['cij'] > 0 for r in rows)}")
PY
  done
}
check parallelogram "$example" --coupled-pairs --pair ground:coupler
/usr/bin/python3 - "$work/parallelogram-petsc-2.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
assert (j["FN"], j["CN"]) == (1, 1), (j["FN"], j["CN"])
rows = j["pairs"]
first = rows[0]  # the pair asked for first: ground and coupler, no direct coupling
assert sorted(b if isinstance(b, str) else b["name"] for b in first["bodies"]) == ["coupler", "ground"], first
assert (first["coupling"], first["f"], first["fij"], first["c"], first["cij"]) == (None, 3, 1, 0, 0), first
coupled = rows[1:]
assert sorted(r["coupling"] for r in coupled) == ["A", "B", "C", "D", "E", "H"], coupled
for r in coupled:
    assert (r["f"], r["fij"], r["c"], r["cij"]) == (1, 1, 2, 1), r
print("parallelogram-redundant: the hand-derived fij and cij")
PY
# The ladder: every coupled pair and three pairs of bodies that are not coupled directly.
check ladder "$ladder" --coupled-pairs --pair u0:v5 --pair u3:u7 --pair v100:u120
/usr/bin/python3 - "$work/ladder-petsc-2.json" <<'PY'
import json, sys
rows = json.load(open(sys.argv[1]))["pairs"]
assert len(rows) == 3 + 499, len(rows)
assert any(r["fij"] > 0 for r in rows) and any(r["cij"] > 0 for r in rows) and any(r["cij"] == 0 for r in rows), "no variety"
PY
# A framework has no pairs: refused with exit 2 on every process.
status=0
"$mpirun" -n 2 "$kinestat" analyze --backend petsc "$source/examples/braced-square.yaml" --coupled-pairs 2> "$work/err" || status=$?
[ "$status" -eq 2 ] || { echo "framework with --coupled-pairs: exit $status, expected 2"; cat "$work/err"; exit 1; }
grep -q "not used by a framework model" "$work/err"
# A pair naming no body: exit 2 before any factorisation.
status=0
"$mpirun" -n 2 "$kinestat" analyze --backend petsc "$example" --pair ground:nobody 2> "$work/err" || status=$?
[ "$status" -eq 2 ] || { echo "bad --pair: exit $status, expected 2"; cat "$work/err"; exit 1; }
grep -q "names no body" "$work/err"
echo "ok"

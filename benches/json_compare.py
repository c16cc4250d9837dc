#!/usr/bin/env python3
"""Compare two rollbench JSON reports field by field (linear time).

    json_compare.py BEFORE.json AFTER.json [--tol 1e-9]

Same rule as shared/tools/json-diff: every numeric leaf of BEFORE must exist in AFTER and
agree to TOL relative to the largest magnitude of that field across the report (array
indices folded, so per-lamina values near zero are judged on their field's scale); strings,
booleans and nulls must be equal; fields only in AFTER are allowed (listed as added). Wall
times and solver statistics are ignored. json-diff rebuilds a dict per AFTER leaf, which is
quadratic on a 1.7 MB report with a thermal transient; this is the same check in one pass.
Exit 0 when all agree."""
import json, re, sys

IGNORE = ("stats", "wall_time")
IDX = re.compile(r"\[\d+\]")

def leaves(obj, path=""):
    if isinstance(obj, dict):
        for k, v in obj.items():
            yield from leaves(v, f"{path}.{k}" if path else k)
    elif isinstance(obj, list):
        for i, v in enumerate(obj):
            yield from leaves(v, f"{path}[{i}]")
    else:
        yield path, obj

def is_num(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)

def main(argv):
    tol = 1e-9
    args = list(argv)
    if "--tol" in args:
        i = args.index("--tol"); tol = float(args[i + 1]); del args[i:i + 2]
    if len(args) != 2:
        sys.exit(__doc__)
    before, after = (json.load(open(p)) for p in args)
    b = dict(leaves(before)); a = dict(leaves(after))
    scale = {}
    for p, v in b.items():
        if is_num(v):
            k = IDX.sub("[]", p)
            scale[k] = max(scale.get(k, 0.0), abs(v))
    bad, n = [], 0
    for p, v in b.items():
        if any(s in p for s in IGNORE):
            continue
        if p not in a:
            bad.append((float("inf"), f"{p}: gone")); continue
        w = a[p]
        if is_num(v) and is_num(w):
            n += 1
            e = abs(w - v) / max(scale[IDX.sub("[]", p)], 1e-300)
            if e > tol:
                bad.append((e, f"{p}: {v!r} -> {w!r} ({e:.1e})"))
        elif v != w:
            bad.append((float("inf"), f"{p}: {v!r} -> {w!r}"))
    added = [p for p in a if p not in b]
    bad.sort(key=lambda t: -t[0])
    for _, line in bad[:20]:
        print(line)
    print(f"{n} numeric fields compared, {len(bad)} differ beyond {tol:g}, {len(added)} added")
    return 1 if bad else 0

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

#!/usr/bin/env python3
"""A hostile user's campaign against the rollbench binary (issue 24's "done means").

    benches/hostile.py [BINARY] [--runs N] [--seed S] [--timeout SECONDS]

Four kinds of abuse, counted:

* random in-range `--set` (one to three keys at a time) over every key of every system,
  read from `rollbench keys --type T` (values drawn log-uniformly inside the printed range,
  the range's ends, and every choice of a choice key), run on every shipped deck;
* malformed decks: random byte edits of the shipped decks, through `check`;
* file tricks: outputs through /dev/stdout appended to a file, two outputs naming one file,
  a planted symlink at a temporary's name, unwritable and full destinations, a FIFO
  without a reader; the files that were there must be there afterwards, unchanged unless
  the command said it wrote them;
* what the successes say: every number in a JSON report finite (serde writes NaN as
  null), a bulk temperature above 400 °C or a negative contact angle only with a warning.

A failure is a panic (exit 101 or a signal), a hang (past the timeout), a message with
Rust debug text, a file lost or replaced, a non-finite number or an unwarned absurd
success. Exit 0 when there are none. The same seed gives the same runs.
"""
import argparse
import json
import math
import os
import random
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DECKS = sorted(
    os.path.join(ROOT, "decks", f)
    for f in os.listdir(os.path.join(ROOT, "decks"))
    if f.endswith(".toml") and not f.endswith(".study.toml")
)
DEBUG_TEXT = re.compile(r"\b[A-Z][A-Za-z]+ \{ [a-z_]+: |panicked at|RUST_BACKTRACE")


def deck_type(path):
    for line in open(path, encoding="utf-8"):
        m = re.match(r'\s*type\s*=\s*"([^"]+)"', line)
        if m:
            return m.group(1)
    return "spherical-roller"


def deck_units(path):
    for line in open(path, encoding="utf-8"):
        m = re.match(r'\s*units\s*=\s*"([^"]+)"', line)
        if m:
            return m.group(1)
    return "us"


RANGE = re.compile(
    r"^(?P<lo>-?[\d.e+-]+)\s*(?P<lop>≤|<)\s*value\s*(?P<hip>≤|<)\s*(?P<hi>-?[\d.e+-]+)"
)


def keys_of(binary, system):
    """{key: ('range', lo, hi) | ('choice', [..])} in SI and US columns."""
    out = subprocess.run(
        [binary, "keys", "--type", system], capture_output=True, text=True, timeout=30
    ).stdout
    keys = {}
    for line in out.splitlines()[1:]:
        parts = re.split(r"\s{2,}", line.strip())
        if len(parts) < 3 or "<" in parts[0] or "." not in parts[0]:
            continue
        key, si, us = parts[0], parts[1], parts[2]
        spec = {}
        for units, text in (("si", si), ("us", us)):
            m = RANGE.match(text)
            if m:
                spec[units] = ("range", float(m["lo"]), float(m["hi"]))
            elif "|" in text:
                spec[units] = ("choice", [c.strip() for c in text.split("|")])
        if spec:
            keys[key] = spec
    return keys


def draw(rng, spec):
    if spec[0] == "choice":
        return rng.choice(spec[1])
    lo, hi = spec[1], spec[2]
    r = rng.random()
    if r < 0.1:
        v = lo
    elif r < 0.2:
        v = hi
    elif lo > 0 and hi / max(lo, 1e-300) > 100:
        v = math.exp(rng.uniform(math.log(max(lo, hi * 1e-12)), math.log(hi)))
    elif lo >= 0 and hi > 0 and r < 0.6:
        v = math.exp(rng.uniform(math.log(max(lo, hi * 1e-9, 1e-300)), math.log(hi)))
    else:
        v = rng.uniform(lo, hi)
    if spec[1] == int(spec[1]) and spec[2] == int(spec[2]) and abs(spec[2]) <= 1000:
        v = round(v)
    return repr(v) if isinstance(v, float) else str(v)


# A null in a report means "not applicable" (an unloaded lamina has no film, a bearing
# that never skids has no threshold speed); these results of a solved case must never
# be null: a null there is a NaN or infinity that serde wrote as null.
MUST_BE_FINITE = re.compile(
    r"(temperature|heat|power|torque|cage_speed|max_.*stress|l10|life_h|stiffness)"
)


def finite_numbers(value, path="", bad=None):
    bad = [] if bad is None else bad
    if isinstance(value, dict):
        # A contact without a film (unloaded, or no EHD film) has no film temperature.
        no_film = not value.get("central_film_m") or not value.get("normal_load_n", 1.0)
        for k, v in value.items():
            if k.endswith("temperature_rise_c") and no_film:
                continue
            if v is None and MUST_BE_FINITE.search(k) and "laminae" not in path:
                bad.append(f"{path}.{k}")
            finite_numbers(v, f"{path}.{k}", bad)
    elif isinstance(value, list):
        for i, v in enumerate(value[:200]):
            finite_numbers(v, f"{path}[{i}]", bad)
    elif isinstance(value, float) and not math.isfinite(value):
        bad.append(path)
    return bad


def absurd_unwarned(report):
    """Absurd successes with no warning in the report's `warnings` (the seed's 400 °C
    limit of the lubricant; a ball contact angle below zero)."""
    warnings = " ".join(str(w) for w in report.get("warnings", []) or [])
    found = []
    bulk = (report.get("heat") or {}).get("bulk_temperature_c", report.get("bulk_temperature_c"))
    if isinstance(bulk, (int, float)) and bulk > 400 and "temperature" not in warnings:
        found.append(f"bulk temperature {bulk:.0f} °C unwarned")
    for ball in report.get("balls", []) or []:
        for race in ("inner", "outer"):
            angle = (ball.get(race) or {}).get("contact_angle_deg")
            if isinstance(angle, (int, float)) and angle < 0 and "angle" not in warnings:
                found.append(f"{race} contact angle {angle:.2f}° unwarned")
                return found
    return found


class Tally:
    def __init__(self):
        self.counts = {}
        self.failures = []

    def add(self, kind, detail=None):
        self.counts[kind] = self.counts.get(kind, 0) + 1
        if detail is not None:
            self.failures.append(f"{kind}: {detail}")


def run(cmd, timeout, **kw):
    try:
        p = subprocess.run(cmd, capture_output=True, timeout=timeout, **kw)
        return p.returncode, p.stdout, p.stderr.decode("utf-8", "replace")
    except subprocess.TimeoutExpired:
        return None, b"", ""


def classify(tally, cmd, code, out, err, check_json):
    label = " ".join(os.path.basename(c) if c.startswith("/") else c for c in cmd[1:])
    if code is None:
        tally.add("hang", label)
    elif code == 101 or code < 0:
        tally.add("panic or signal", f"{label}: exit {code}: {err[-300:]}")
    elif DEBUG_TEXT.search(err):
        tally.add("debug text in message", f"{label}: {err[:300]}")
    elif code == 0:
        if check_json:
            try:
                report = json.loads(out)
            except ValueError:
                tally.add("unparsable JSON", label)
                return
            bad = finite_numbers(report)
            if bad:
                tally.add("non-finite success", f"{label}: {bad[:3]}")
                return
            absurd = absurd_unwarned(report)
            if absurd:
                tally.add("absurd unwarned success", f"{label}: {absurd}")
                return
        tally.add("solved")
    elif code in (1, 2, 64):
        tally.add(f"refused or failed (exit {code})")
    else:
        tally.add("unexpected exit", f"{label}: exit {code}: {err[:200]}")


def campaign_sets(binary, rng, runs, timeout, tally):
    systems = {}
    for deck in DECKS:
        systems.setdefault(deck_type(deck), keys_of(binary, deck_type(deck)))
    for i in range(runs):
        deck = DECKS[i % len(DECKS)]
        keys = systems[deck_type(deck)]
        units = deck_units(deck)
        chosen = rng.sample(sorted(keys), k=min(len(keys), rng.choice([1, 1, 2, 3])))
        cmd = [binary, "run", deck, "--format", "json"]
        for k in chosen:
            spec = keys[k].get(units) or next(iter(keys[k].values()))
            cmd += ["--set", f"{k}={draw(rng, spec)}"]
        code, out, err = run(cmd, timeout)
        classify(tally, cmd, code, out, err, check_json=True)


def campaign_malformed(binary, rng, runs, timeout, tally):
    with tempfile.TemporaryDirectory() as d:
        for i in range(runs):
            text = bytearray(open(DECKS[i % len(DECKS)], "rb").read())
            for _ in range(rng.randint(1, 8)):
                op = rng.random()
                at = rng.randrange(len(text))
                if op < 0.4:
                    text[at] = rng.randrange(256)
                elif op < 0.7:
                    del text[at : at + rng.randint(1, 40)]
                else:
                    text[at:at] = rng.choice(
                        [b"[", b"]", b"=", b'"', b"\n", b"1e999", b"-", b"nan", b"{", b"x" * 5000]
                    )
            path = os.path.join(d, f"m{i}.toml")
            open(path, "wb").write(bytes(text))
            code, out, err = run([binary, "check", path], timeout)
            if code in (0, 1):
                classify(tally, [binary, "check", path], 1 if code else 0, out, err, False)
            else:
                classify(tally, [binary, "check", path], code if code is not None else None, out, err, False)


def campaign_files(binary, timeout, tally):
    """Each trick: set up files, run, check what must survive."""
    deck = os.path.join(ROOT, "decks", "chen_a.toml")
    with tempfile.TemporaryDirectory() as d:
        def fresh(name, text):
            p = os.path.join(d, name)
            if os.path.lexists(p):
                os.remove(p)
            with open(p, "w") as f:
                f.write(text)
            return p

        def survived(what, path, text):
            ok = os.path.exists(path) and open(path).read().startswith(text)
            tally.add("file kept" if ok else "file lost or replaced", None if ok else what)

        # 1. appending through /dev/stdout keeps the file's head.
        for target in ["/dev/stdout", "/dev/fd/1", "/proc/self/fd/1"]:
            log = fresh("log.txt", "keep\n")
            with open(log, "ab") as f:
                subprocess.run(
                    [binary, "run", deck, "--format", "csv", "--output", target],
                    stdout=f, stderr=subprocess.DEVNULL, timeout=timeout,
                )
            survived(f"append through {target}", log, "keep\n")
        # 2. --output and --series naming one new file.
        for a, b in [("new.json", "./new.json"), ("new2.json", os.path.join(d, "new2.json"))]:
            for f in ("new.json", "new2.json"):
                if os.path.exists(os.path.join(d, f)):
                    os.remove(os.path.join(d, f))
            code, _, _ = run(
                [binary, "run", deck, "--set", "dynamics.method=time-simulation",
                 "--set", "dynamics.orbits=1", "--output", a, "--series", b],
                timeout, cwd=d,
            )
            tally.add("same-file outputs refused" if code not in (0, None) else "file lost or replaced",
                      None if code not in (0, None) else f"--output {a} --series {b} exit {code}")
        # 3. a planted symlink at an old-style temporary name never redirects the write.
        victim = fresh("victim.txt", "victim\n")
        out = os.path.join(d, "out.json")
        for pid in range(os.getpid(), os.getpid() + 3):
            link = os.path.join(d, f".out.json.tmp-{pid}")
            if not os.path.lexists(link):
                os.symlink(victim, link)
        run([binary, "run", deck, "--output", out], timeout)
        survived("planted temporary symlink", victim, "victim\n")
        # 4. a failing second output leaves the first untouched.
        rep = fresh("rep.json", "old report\n")
        run([binary, "run", deck, "--set", "dynamics.method=time-simulation",
             "--set", "dynamics.orbits=1", "--output", rep, "--series",
             os.path.join(d, "no", "such", "s.csv")], timeout)
        survived("--series into a missing directory", rep, "old report\n")
        if os.path.exists("/dev/full"):
            rep = fresh("rep.json", "old report\n")
            run([binary, "run", deck, "--set", "dynamics.method=time-simulation",
                 "--set", "dynamics.orbits=1", "--output", rep, "--series", "/dev/full"], timeout)
            survived("--series /dev/full", rep, "old report\n")
        # 5. a sweep where no point solves keeps the old file.
        old = fresh("f.csv", "old sweep\n")
        run([binary, "sweep", os.path.join(ROOT, "decks", "trb_afapl.toml"), "--set-range",
             "operating.axial_load=-3000:-1000:1000", "--output", old], timeout)
        survived("failed sweep", old, "old sweep\n")
        # 6. a FIFO without a reader does not hang.
        fifo = os.path.join(d, "fifo")
        os.mkfifo(fifo)
        code, _, _ = run([binary, "run", deck, "--output", fifo], timeout)
        tally.add("hang" if code is None else "FIFO answered", "--output FIFO" if code is None else None)
        # 7. no temporary left behind.
        left = [f for f in os.listdir(d) if ".tmp" in f and not os.path.islink(os.path.join(d, f))]
        tally.add("temporaries left" if left else "no temporaries left", left or None)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("binary", nargs="?", default=os.path.join(ROOT, "target", "release", "rollbench"))
    ap.add_argument("--runs", type=int, default=400)
    ap.add_argument("--seed", type=int, default=24)
    ap.add_argument("--timeout", type=float, default=30.0)
    a = ap.parse_args()
    rng = random.Random(a.seed)
    tally = Tally()
    campaign_sets(a.binary, rng, a.runs, a.timeout, tally)
    campaign_malformed(a.binary, rng, a.runs // 2, a.timeout, tally)
    campaign_files(a.binary, a.timeout, tally)
    for k in sorted(tally.counts):
        print(f"{tally.counts[k]:6d}  {k}")
    bad_kinds = ("hang", "panic", "debug text", "lost", "non-finite", "absurd", "unexpected", "unparsable", "temporaries left")
    failures = [f for f in tally.failures if any(k in f.split(":")[0] for k in bad_kinds)]
    for f in failures[:40]:
        print("FAIL", f)
    print(f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

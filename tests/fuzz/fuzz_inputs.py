#!/usr/bin/env python3
"""Fuzz test of the vahf command: mutated input files must never crash it.

Whatever the input, vahf exits 0, 1 (a failure of the
computation, stated) or 2 (bad input, in one line). This script takes the
repository's own files as mutation bases, mutates them with a seeded
generator and runs vahf on every mutant:

  bases     experiments/scenes/*.json            scenes
            experiments/*.json                   experiments (scene and lab paths
                                                 relative to the experiment's folder)
            data/synthetic_block, data/paper     lab datasets (dataset.json + CSV)
            data/synthetic_block/generator.json  the synthetic-lab generator
            built in                             a parameter-override file (vahf-overrides/1:
                                                 none ships in the repository) and a lab
                                                 dataset with all four CSV kinds (trials,
                                                 segments, summaries, tracks), both as
                                                 docs/calibration.md and docs/lab-data.md
                                                 show them
  mutations numbers replaced by extremes (0, -1, 1e-300, 1e300, 1e308, -1e308,
            huge integers, 1e23, values just outside the documented ranges),
            NaN-like strings and raw non-JSON numbers (NaN, Infinity, 1e400),
            wrong JSON types, a required key deleted, an unknown key added, a
            key duplicated (in the raw text), deep nesting, empty arrays and
            objects, very long strings, "format"/"kind"/enum values changed, the
            file swapped for another kind of vahf file, paths pointing elsewhere,
            model parameters set to extremes, geometry scaled or made huge; CSV
            cells corrupted (text in numeric columns, nan, 1e300, empty), columns
            missing or extra, rows short or long, empty files, NUL bytes,
            unclosed quotes, huge files; files truncated; and combinations of
            2 or 3 of these. A "cli" class mutates `vahf trial`'s options.
  runs      `vahf check FILE` on every mutant; for a scene mutant that check
            accepts, `vahf trial FILE --seed 1` and for some an `--integrator`,
            `--position` or `--trial` variant. To keep CI time down, every scene
            mutant starts from its base with simulation/time_limit lowered to
            --time-limit seconds (default 1) and simulation/max_steps to
            --max-steps (default 20000) before it is mutated, so a trial
            simulates at most that long and takes at most that many steps
            unless a mutation changes them (vahf's own budget, 1e6 steps,
            then bounds it). Each trial's command line also sets both
            budgets: --max-steps and simulation/max_contact_tests to
            --max-contact-tests (default 2e9), which bounds what a step costs.
  asserts   per run: exit status in {0, 1, 2}; not killed by a signal; not
            over its CPU limit (--timeout, default 120 s of CPU per process,
            and 4x that plus 60 s of wall); on exit 2, stderr
            is exactly one line starting with "vahf: error: ".
  records   "check accepts what trial rejects": `check` says "valid scene"
            (exit 0) and `trial` exits 2. The input rules want none; they are counted
            apart and fail the run only with --strict-check.

Generation is deterministic: mutant i is made by its own random.Random seeded
from (seed, i), and all mutants are generated and written, in order, before
any runs; results do not depend on --jobs. `--only I,J` regenerates and runs
mutants I and J alone. Each failure is kept under OUT/failures/ with the mutant, the
command line (cmd.sh), stdout, stderr and the mutations that made it; the
mutant also stays in OUT/tree/, where relative paths resolve. A summary line
per class, the failures grouped by signature, and OUT/summary.json end the run.

Exit status: 0 no failure; 1 at least one failure; 2 bad usage.

Environment: VAHF_FUZZ_FILES and VAHF_FUZZ_SEED set the defaults of --files
and --seed (for long soaks); an explicit option wins.

Python 3 standard library only.
"""

import argparse
import concurrent.futures
import copy
import csv
import io
import json
import math
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time

try:
    import resource  # POSIX: limits the address space of vahf's processes
except ImportError:  # pragma: no cover
    resource = None

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

csv.field_size_limit(2 ** 31 - 1)  # a mutant's field may be megabytes long

DEFAULT_FILES = 1500  # the CI size: at most about 5 minutes on one core (FINDINGS.md)
DEFAULT_SEED = 13
OUT_MARKER = ".vahf-fuzz-out"
ERROR_PREFIX = "vahf: error: "

FORMATS = ["vahf-scene/1", "vahf-experiment/1", "vahf-lab/1", "vahf-overrides/1",
           "vahf-synthetic/1", "vahf-scene/2", "vahf-scene", "VAHF-SCENE/1", "", "scene"]


def registry_names(param):
    """The names `vahf params` lists in the rule of PARAM, a registry's choice
    (docs/parameters.md, its output): simulation/integrator's are the steppers'
    (src/vahf/scene/steppers.def), contact/model's the contact models'
    (src/vahf/contact/contact_registry.cc)."""
    with open(os.path.join(REPO, "docs", "parameters.md"), encoding="utf-8") as f:
        m = re.search(r"^\| `%s` \| [^|]* \| ([^|]*) \|" % re.escape(param), f.read(), re.M)
    if not m:
        sys.exit("fuzz_inputs.py: docs/parameters.md has no %s row" % param)
    return [name.strip() for name in m.group(1).split(",")]


INTEGRATORS = registry_names("simulation/integrator")


def kind_names():
    """The experiment kinds as docs/kinds.md (`vahf kinds`, the registry's
    output: src/vahf/kinds/kinds.def) lists them, in its order."""
    with open(os.path.join(REPO, "docs", "kinds.md"), encoding="utf-8") as f:
        names = re.findall(r"^\| `([a-z_0-9]+)` \|", f.read(), re.M)
    if not names:
        sys.exit("fuzz_inputs.py: docs/kinds.md lists no kinds")
    return names


KINDS = kind_names() + ["", "Table1"]
ENUMS = {
    "role": ["base", "assembling", "assembled", "fixed", ""],
    "sex": ["male", "female", "unspecified", "other", ""],
    "type": ["revolution", "box", "sphere", ""],
    "integrator": INTEGRATORS + ["Euler", ""],
    "mode": ["operator", "none", "raycast", "constant", "off", "on"],
    "model": registry_names("contact/model") + ["revolved", "rigid"],
    "solver": ["levenberg_marquardt", "golden_section", "newton"],
    "quantity": ["assembly_time", "success_rate", "eta", "lambda_c", "V", "f", "r", "g", "x"],
    "by": ["operator", "all", "part"],
    "part": ["all", "block", "piston_rod", "guide_sleeve", "seal_ring", "peg", "nothing"],
    "condition": ["virtual", "real", "standard", "general", ""],
}
UNITS = ["m", "cm", "mm", "s", "ms", "min", "ft", "h", ""]
for _k in ("height", "arm_length", "time", "start", "end", "mean_time", "instant", "position"):
    ENUMS[_k] = UNITS  # a lab manifest's units (string values only: see m_enum)

# Extremes for any number.
EXTREMES = [0, 0.0, -0.0, -1, 1, 1e-300, -1e-300, 1e300, -1e300, 1e308, -1e308, 5e-324,
            1.7976931348623157e308, 1e23, 1e-12, 1e12, 2 ** 31, 2 ** 32 + 1, 2 ** 53 + 1,
            2 ** 63, 2 ** 64 - 1, 2 ** 64, 2 ** 64 + 1, -(2 ** 63) - 1, 10 ** 30, 10 ** 400,
            0.5, 1.5]
# JSON text that is not a plain number, or one that overflows a double.
RAW_NUMBERS = ["NaN", "Infinity", "-Infinity", "1e400", "-1e400", "1e-400", "-0", "1E+2",
               "0x10", "01", ".5", "1.", "+1", "1e", "--1", "1_000", "0.1e-2147483649"]
NAN_STRINGS = ["nan", "NaN", "inf", "-inf", "Infinity", "1e5", "0", "", " 1", "1 m"]

# Documented ranges (docs/scene-format.md, docs/parameters.md, docs/lab-data.md) by the
# last key of a value's path: values just outside them, and the edges themselves.
def _around(lo=None, hi=None):
    """The bounds lo and hi, and the doubles just beyond them."""
    out = []
    for b, below in ((lo, True), (hi, False)):
        if b is None:
            continue
        out += [math.nextafter(float(b), -math.inf if below else math.inf),
                b - 1e-9 * max(1.0, abs(b)) if below else b + 1e-9 * max(1.0, abs(b)),
                float(b)]
    return out


RANGE_EDGES = {
    "height": _around(1.0, 2.5), "arm_length": _around(0.3, 1.2) + _around(0.4, 1.2),
    "facing_deg": _around(-360, 360), "mass": _around(0, None),
    "density": _around(0, None), "friction": _around(0, None),
    "accuracy": _around(0, 1), "seed": [-1, 2 ** 64, 2 ** 64 - 1, 0],
    "trials": [0, -1, 1, 2 ** 31, 2 ** 63], "noise_trials": [0, -1, 2 ** 31],
    "repetitions": [0, -1, 2 ** 31], "repetition": [0, -1, 2 ** 31],
    "max_iterations": [0, -1, 2 ** 31], "relative_step": [0, -1e-9, 1, 1e-300],
    "tolerance": [0, -1e-9, 1e300], "duration_min": [0, -1, 1e300, 1e-300],
    "segments": [0, -1, 2 ** 31, 1], "pilot_cycles": [0, -1, 2 ** 31],
    "instants_s": [-1, 0, 1e300], "paper_cycle_s": [0, -1, 1e-300, 1e300],
    "time_sd": [-1e-9, 0, 1e300], "time_resolution": [-1e-9, 0, 1e300],
    "scale": [0, -1, 1e-300, 1e300], "margin": [0, -1, 1e300],
    "start": [0, -1, 1e300], "lower": [0, -1, 1e300], "upper": [0, -1, 1e300],
    "segment": [0, -1, 2 ** 31], "value": _around(0, 1),
}

# Model parameters as `vahf params` names them, with rule-edge values; read from
# docs/parameters.md when it can be parsed, else this fallback.
FALLBACK_PARAMS = {
    "simulation/accuracy": _around(0, 1), "simulation/time_limit": [1e-300, 1e300, 0],
    "simulation/decision_interval": [1e-9, 1e-300, 1e300, 0],
    "simulation/fixed_step": [1e-12, 1e300], "contact/shell_spacing": [1e-9, 1e-6, 1e300],
    "contact/stiffness": [1e300, 1e-300], "visibility/grid": [0, 2 ** 31, 100000],
    "guidance/kappa": [1e-300, 1e300], "fatigue/a_max": [1e-300, 1e300],
}


def load_param_table():
    params = {}
    try:
        with open(os.path.join(REPO, "docs", "parameters.md"), encoding="utf-8") as f:
            text = f.read()
    except OSError:
        return dict(FALLBACK_PARAMS)
    for m in re.finditer(r"^\| `([a-z_]+/[a-z0-9_]+)` \| [^|]* \| ([^|]*) \| ([^|]*) \|", text,
                         re.M):
        name, rule, default = m.group(1), m.group(2).strip(), m.group(3).strip()
        vals = [0, -1, 1e-300, 1e300, 1e308]
        r = re.match(r"in ([\[(])([-\d.e]+), ([-\d.e]+)([\])])", rule)
        i = re.match(r"integer in \[(-?\d+), (-?\d+)\]", rule)
        if r:
            vals += _around(float(r.group(2)), float(r.group(3)))
        elif i:
            lo, hi = int(i.group(1)), int(i.group(2))
            vals += [lo - 1, lo, hi, hi + 1, 2 ** 31, 2 ** 63, 1.5]
        elif rule.startswith(">"):
            vals += [math.nextafter(0.0, -1.0), 5e-324]
        else:  # an enumeration: its members, and a wrong one
            vals = [s.strip() for s in rule.split(",")] + ["nonsense", ""]
        try:
            vals.append(float(default) * 1e6)
        except ValueError:
            pass
        params[name] = vals
    return params or dict(FALLBACK_PARAMS)


# ---------------------------------------------------------------------------
# JSON with verbatim text and duplicate keys

class Raw:
    """A value written verbatim (not JSON, or nested deeper than Python recurses)."""
    __slots__ = ("text",)

    def __init__(self, text):
        self.text = text


class DupKey:
    """An object key written as `name`: lets one object hold a key twice."""
    __slots__ = ("name",)

    def __init__(self, name):
        self.name = name


def dump(v, out):
    if isinstance(v, Raw):
        out.append(v.text)
    elif v is None:
        out.append("null")
    elif v is True:
        out.append("true")
    elif v is False:
        out.append("false")
    elif isinstance(v, int):
        out.append(str(v))
    elif isinstance(v, float):
        out.append(repr(v) if math.isfinite(v) else
                   ("NaN" if v != v else ("Infinity" if v > 0 else "-Infinity")))
    elif isinstance(v, str):
        out.append(json.dumps(v))
    elif isinstance(v, list):
        out.append("[")
        for i, x in enumerate(v):
            if i:
                out.append(",")
            dump(x, out)
        out.append("]")
    elif isinstance(v, dict):
        out.append("{")
        for i, (k, x) in enumerate(v.items()):
            if i:
                out.append(",")
            out.append(json.dumps(k.name if isinstance(k, DupKey) else k))
            out.append(":")
            dump(x, out)
        out.append("}")
    else:
        raise TypeError(type(v))


def to_text(v):
    out = []
    dump(v, out)
    return "".join(out) + "\n"


def walk(v, path=()):
    """Every (path, value) in document order; a path is a tuple of keys and indices."""
    yield path, v
    if isinstance(v, dict):
        for k, x in list(v.items()):
            if not isinstance(k, DupKey):
                yield from walk(x, path + (k,))
    elif isinstance(v, list):
        for i, x in enumerate(v):
            yield from walk(x, path + (i,))


def get_at(root, path):
    for p in path:
        root = root[p]
    return root


def set_at(root, path, value):
    if not path:
        return value
    get_at(root, path[:-1])[path[-1]] = value
    return root


def is_number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def pointer(path):
    return "/" + "/".join(str(p).replace("~", "~0").replace("/", "~1") for p in path)


def short(v, n=40):
    if isinstance(v, Raw):
        s = v.text
    else:
        try:
            s = to_text(v).strip()
        except (TypeError, RecursionError):
            s = repr(v)
    return s if len(s) <= n else s[:n] + "...(%d chars)" % len(s)


# ---------------------------------------------------------------------------
# Bases

def read_text(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def load_json(path):
    return json.loads(read_text(path))


BUILTIN_OVERRIDES = {
    "format": "vahf-overrides/1",
    "source": "calibrate experiment 'calibrate_synthetic' (vahf run)",
    "parameters": {"guidance/kappa": 249.2},
}

# docs/lab-data.md's example dataset, every CSV kind in one.
DOC_LAB = {
    "dataset.json": to_text({
        "format": "vahf-lab/1",
        "name": "example",
        "description": "Two operators assembling the cylinder, and one fatigue series.",
        "provenance": {"source": "synthetic: written by hand for docs/lab-data.md",
                       "recorded": "2026-11-01", "notes": "statures measured barefoot"},
        "trials": {"file": "trials.csv",
                   "units": {"height": "mm", "arm_length": "mm", "time": "s"}},
        "segments": {"file": "segments.csv",
                     "units": {"start": "min", "end": "min", "mean_time": "s"}},
        "summaries": {"file": "summaries.csv"},
        "tracks": [{"file": "tracks/op1_rep1.csv", "operator": "male 1", "condition": "good",
                    "repetition": 1, "units": {"time": "s", "position": "m"}}],
    }),
    "trials.csv": (
        "# Lab of the example; statures measured barefoot, in mm.\n"
        "operator,sex,height,arm_length,condition,part,repetition,time,success,note\n"
        "male 1,male,1750,740,good,piston_rod,1,15.2,1,\n"
        "male 1,male,1750,740,good,piston_rod,2,,0,\"dropped, \"\"twice\"\"\"\n"
        "female 1,female,1620,680,good,all,1,16.75,1,\n"
        "female 1,female,1620,680,good,all,2,17.1,1,\n"),
    "segments.csv": (
        "segment,start,end,attempts,successes,mean_time,condition,source\n"
        "1,0,15,25,23,16.1,real,Sec. 5.4\n"
        "2,15,30,25,21,16.9,real,Sec. 5.4\n"),
    "summaries.csv": (
        "quantity,part,condition,segment,instant,value,sd,n,uncertainty,source\n"
        "assembly_time,all,,,,16,,,,\"Sec. 5.2: \"\"about 16 s\"\"\"\n"
        "eta,piston_rod,,,3,0.05,,,,Table 1 (instant a)\n"),
    "tracks/op1_rep1.csv": (
        "time,part_x,part_y,part_z,brow_x,brow_y,brow_z,lshoulder_x,lshoulder_y,lshoulder_z,"
        "rshoulder_x,rshoulder_y,rshoulder_z,body_x,body_y,body_z,visibility\n"
        "0,0.1,0.2,0.9,0,-0.4,1.6,-0.2,-0.45,1.4,0.2,-0.45,1.4,0,-0.45,1.1,1\n"
        "0.1,0.1,0.2,0.89,0,-0.4,1.6,-0.2,-0.45,1.4,0.2,-0.45,1.4,0,-0.45,1.1,\n"
        "0.2,0.1,0.2,0.88,0,-0.4,1.6,-0.2,-0.45,1.4,0.2,-0.45,1.4,0,-0.45,1.1,0.5\n"),
}


class Bases:
    def __init__(self, time_limit, max_steps=0):
        self.scenes = {}       # name -> doc (time limit lowered)
        self.experiments = {}  # name -> doc
        self.labs = {}         # name -> {relpath: text}
        self.generators = {}
        self.overrides = {"builtin_overrides": BUILTIN_OVERRIDES}
        sdir = os.path.join(REPO, "experiments", "scenes")
        for f in sorted(os.listdir(sdir)):
            if f.endswith(".json"):
                doc = load_json(os.path.join(sdir, f))
                if time_limit > 0:
                    sim = doc.setdefault("parameters", {}).setdefault("simulation", {})
                    sim["time_limit"] = time_limit
                if max_steps > 0:
                    sim = doc.setdefault("parameters", {}).setdefault("simulation", {})
                    sim["max_steps"] = max_steps
                self.scenes["scenes/" + f] = doc
        edir = os.path.join(REPO, "experiments")
        for f in sorted(os.listdir(edir)):
            if f.endswith(".json"):
                self.experiments[f] = load_json(os.path.join(edir, f))
        for d in sorted(os.listdir(os.path.join(REPO, "data"))):
            ddir = os.path.join(REPO, "data", d)
            if os.path.isfile(os.path.join(ddir, "dataset.json")):
                files = {}
                for root, _, names in os.walk(ddir):
                    for n in sorted(names):
                        if n.endswith(".csv") or n == "dataset.json":
                            p = os.path.join(root, n)
                            files[os.path.relpath(p, ddir)] = read_text(p)
                self.labs["data/" + d] = files
            g = os.path.join(ddir, "generator.json")
            if os.path.isfile(g):
                self.generators["data/%s/generator.json" % d] = (d, load_json(g))
        self.labs["docs/lab-data.md example"] = dict(DOC_LAB)
        self.param_table = load_param_table()
        self.all_docs = ([("scene", d) for d in self.scenes.values()] +
                         [("experiment", d) for d in self.experiments.values()] +
                         [("lab", json.loads(f["dataset.json"])) for f in self.labs.values()] +
                         [("generator", d) for _, d in self.generators.values()] +
                         [("overrides", BUILTIN_OVERRIDES)])
        self.csv_texts = [t for f in self.labs.values() for n, t in f.items()
                          if n.endswith(".csv")]
        self.keys = sorted({k for _, d in self.all_docs for p, _ in walk(d) for k in p
                            if isinstance(k, str)})


# ---------------------------------------------------------------------------
# JSON mutations: each takes (rng, state) and returns a description, or None
# when it does not apply to this document (another is drawn then).

class State:
    def __init__(self, cls, doc, bases, own_name):
        self.cls = cls
        self.doc = doc
        self.bases = bases
        self.own_name = own_name  # the mutant's file name, as its own folder sees it
        self.byte_ops = []        # applied to the written text, in order
        self.swapped = False


def pick(rng, items):
    return items[rng.randrange(len(items))] if items else None


def nodes(st, pred=lambda p, v: True, root_ok=False):
    return [(p, v) for p, v in walk(st.doc) if (root_ok or p) and pred(p, v)]


def last_key(path):
    for p in reversed(path):
        if isinstance(p, str):
            return p
    return ""


def extreme_for(rng, path):
    key = last_key(path)
    if key in RANGE_EDGES and rng.random() < 0.5:
        return pick(rng, RANGE_EDGES[key])
    return pick(rng, EXTREMES)


def m_number_extreme(rng, st):
    c = nodes(st, lambda p, v: is_number(v))
    if not c:
        return None
    p, v = pick(rng, c)
    new = extreme_for(rng, p)
    while repr(new) == repr(v):
        new = pick(rng, EXTREMES)
    st.doc = set_at(st.doc, p, new)
    return "number %s: %s -> %s" % (pointer(p), short(v), short(new))


def m_number_raw(rng, st):
    c = nodes(st, lambda p, v: is_number(v))
    if not c:
        return None
    p, v = pick(rng, c)
    t = pick(rng, RAW_NUMBERS)
    st.doc = set_at(st.doc, p, Raw(t))
    return "raw number %s: %s -> %s" % (pointer(p), short(v), t)


def m_nan_string(rng, st):
    c = nodes(st, lambda p, v: is_number(v))
    if not c:
        return None
    p, v = pick(rng, c)
    s = pick(rng, NAN_STRINGS)
    st.doc = set_at(st.doc, p, s)
    return "number as string %s: %s -> %s" % (pointer(p), short(v), json.dumps(s))


def other_type(rng, v):
    choices = [None, True, False, 0, 1.5, "text", "", [], {}, [v], {"value": v}, [[1, 2]]]
    choices = [c for c in choices if type(c) is not type(v)]
    return copy.deepcopy(pick(rng, choices))


def m_wrong_type(rng, st):
    c = nodes(st, lambda p, v: not isinstance(v, Raw))
    if not c:
        return None
    p, v = pick(rng, c)
    new = other_type(rng, v)
    st.doc = set_at(st.doc, p, new)
    return "wrong type %s: %s -> %s" % (pointer(p), short(v), short(new))


def m_delete_key(rng, st):
    c = nodes(st, lambda p, v: isinstance(p[-1], str))
    if not c:
        return None
    p, _ = pick(rng, c)
    del get_at(st.doc, p[:-1])[p[-1]]
    return "delete key %s" % pointer(p)


def m_delete_element(rng, st):
    c = nodes(st, lambda p, v: isinstance(p[-1], int))
    if not c:
        return None
    p, _ = pick(rng, c)
    del get_at(st.doc, p[:-1])[p[-1]]
    return "delete element %s" % pointer(p)


def m_unknown_key(rng, st):
    c = nodes(st, lambda p, v: isinstance(v, dict), root_ok=True)
    if not c:
        return None
    p, obj = pick(rng, c)
    known = st.bases.keys
    k = pick(rng, ["fuzz", "densty", "Mass", "", " name", "format\u0000", "\u00e9t\u00e9",
                   pick(rng, known), pick(rng, known), pick(rng, known) + "_"])
    if k in obj:
        return None
    obj[k] = copy.deepcopy(pick(rng, [1, "x", [], {}, None, 1e300, [1, 2, 3]]))
    return "add key %s = %s" % (pointer(p + (k,)), short(obj[k]))


def m_duplicate_key(rng, st):
    c = nodes(st, lambda p, v: isinstance(p[-1], str) and not isinstance(v, Raw))
    if not c:
        return None
    p, v = pick(rng, c)
    obj = get_at(st.doc, p[:-1])
    same = rng.random() < 0.3
    new = copy.deepcopy(v) if same else (extreme_for(rng, p) if is_number(v) else
                                         other_type(rng, v))
    # rebuild the object so that the duplicate follows the original
    items = list(obj.items())
    obj.clear()
    for k, x in items:
        obj[k] = x
        if k == p[-1]:
            obj[DupKey(k)] = new
    return "duplicate key %s (second value %s)" % (pointer(p), short(new))


DEPTHS = [63, 64, 65, 66, 200, 5000, 100000]


def m_deep_nesting(rng, st):
    c = nodes(st, lambda p, v: True)
    if not c:
        return None
    p, _ = pick(rng, c)
    d = pick(rng, DEPTHS)
    kind = rng.randrange(3)
    if kind == 0:
        t = "[" * d + "1" + "]" * d
    elif kind == 1:
        t = '{"a":' * d + "1" + "}" * d
    else:
        t = '[{"a":' * (d // 2) + "[]" + "}]" * (d // 2)
    st.doc = set_at(st.doc, p, Raw(t))
    return "nested %d deep (%s) at %s" % (d, ["arrays", "objects", "mixed"][kind], pointer(p))


def m_empty_container(rng, st):
    c = nodes(st, lambda p, v: isinstance(v, (list, dict)), root_ok=True)
    if not c:
        return None
    p, v = pick(rng, c)
    new = [] if rng.random() < 0.5 else {}
    st.doc = set_at(st.doc, p, new)
    return "empty %s at %s" % (to_text(new).strip(), pointer(p) if p else "root")


LONG = [256, 4096, 65536, 1000000]


def m_long_string(rng, st):
    c = nodes(st, lambda p, v: isinstance(v, str)) or nodes(st)
    if not c:
        return None
    p, v = pick(rng, c)
    n = rng.choices(LONG, [4, 4, 2, 1])[0]
    filler = pick(rng, ["A", "\u00e9", "/", "\\", "%s", "{}", "\u0001", "\ud800", "\u0000"])
    s = (filler * n)[:n]
    st.doc = set_at(st.doc, p, s)
    return "string of %d x %r at %s" % (n, filler, pointer(p))


def m_change_format(rng, st):
    c = nodes(st, lambda p, v: isinstance(v, str) and last_key(p) in ("format", "kind")
              and len(p) <= 2)
    if not c:
        return None
    p, v = pick(rng, c)
    new = pick(rng, FORMATS if last_key(p) == "format" else KINDS)
    if new == v:
        return None
    st.doc = set_at(st.doc, p, new)
    return "%s %s -> %s" % (last_key(p), json.dumps(v), json.dumps(new))


def m_enum(rng, st):
    c = nodes(st, lambda p, v: isinstance(v, str) and last_key(p) in ENUMS)
    if not c:
        return None
    p, v = pick(rng, c)
    new = pick(rng, ENUMS[last_key(p)])
    if new == v:
        return None
    st.doc = set_at(st.doc, p, new)
    return "enum %s: %s -> %s" % (pointer(p), json.dumps(v), json.dumps(new))


def m_swap_kind(rng, st):
    others = [d for cls, d in st.bases.all_docs if cls != st.cls]
    st.doc = copy.deepcopy(pick(rng, others))
    st.swapped = True
    return "file swapped for a %s file (%s)" % (st.doc.get("format", "?"),
                                                st.doc.get("name", "?"))


PATHS = ["scenes/peg_in_hole.json", "scenes/free_move.json", "paper.json", "table1.json",
         "../data/paper/dataset.json", "../data/synthetic_block/dataset.json",
         "../data/synthetic_block/generator.json", "scenes", ".", "", "/", "/dev/null",
         "/dev/zero", "/proc/self/status", "missing.json", "../../../../../etc/passwd",
         "scenes/../scenes/peg_in_hole.json", "scenes//peg_in_hole.json", "a\u0000b.json",
         "trials.csv", "summaries.csv", "dataset.json", "tracks", "../trials.csv",
         "/etc/passwd", "x" * 5000]


def m_path(rng, st):
    c = nodes(st, lambda p, v: isinstance(v, str) and (
        v.endswith((".json", ".csv")) or last_key(p) in ("scene", "lab", "file", "scenes",
                                                         "experiments")))
    if not c:
        return None
    p, v = pick(rng, c)
    new = st.own_name if rng.random() < 0.15 else pick(rng, PATHS)
    st.doc = set_at(st.doc, p, new)
    return "path %s: %s -> %s" % (pointer(p), json.dumps(v), short(new))


def m_set_param(rng, st):
    """A model parameter set to an edge or extreme value, where the file takes them."""
    table = st.bases.param_table
    name = pick(rng, sorted(table))
    value = copy.deepcopy(pick(rng, table[name]))
    if rng.random() < 0.15:
        value = pick(rng, [None, "1", [1], {}, Raw("NaN"), Raw("1e400")])
    group, key = name.split("/")
    doc = st.doc
    if not isinstance(doc, dict):
        return None
    fmt = doc.get("format")
    if fmt == "vahf-scene/1":
        params = doc.setdefault("parameters", {})
        if not isinstance(params, dict):
            return None
        g = params.setdefault(group, {})
        if not isinstance(g, dict):
            return None
        g[key] = value
        return "parameter %s = %s" % (pointer(("parameters", group, key)), short(value))
    # flat "group/key" objects: override files, generators, precision settings
    c = nodes(st, lambda p, v: isinstance(v, dict) and v and all(
        isinstance(k, str) and "/" in k for k in v), root_ok=True)
    if not c:
        if fmt in ("vahf-overrides/1", "vahf-synthetic/1"):
            doc["parameters"] = {}
            c = [(("parameters",), doc["parameters"])]
        else:
            return None
    p, obj = pick(rng, c)
    obj[name] = value
    return "parameter %s = %s" % (pointer(p + (name,)), short(value))


def m_scale(rng, st):
    """Every number under a node (a profile, a size, a pose) scaled together."""
    c = nodes(st, lambda p, v: isinstance(v, (list, dict)) and last_key(p) in (
        "profile", "size", "position", "pose", "geometry", "gravity", "target", "grasp",
        "operator", "rotation_xyz_deg"))
    if not c:
        return None
    p, v = pick(rng, c)
    f = pick(rng, [1e-300, 1e-12, 1e-9, 1e-6, 1e3, 1e6, 1e12, 1e150, 1e300, -1.0, 0.0])
    for q, x in list(walk(v)):
        if is_number(x):
            try:
                y = x * f
            except OverflowError:  # a huge integer times 1e300
                y = math.inf
            v = set_at(v, q, y)
    st.doc = set_at(st.doc, p, v)
    return "numbers under %s scaled by %g" % (pointer(p), f)


def m_big_profile(rng, st):
    c = nodes(st, lambda p, v: last_key(p) == "profile" and isinstance(v, list))
    if not c:
        return None
    p, _ = pick(rng, c)
    n = rng.choices([100, 1000, 10000, 50000], [4, 3, 2, 1])[0]
    shape = rng.randrange(4)
    if shape == 0:  # a sawtooth side: a valid profile with n vertices
        pts = [[0, 0], [0.01, 0]] + [[0.01 + 0.0005 * (i % 2), 0.05 * i / n]
                                     for i in range(1, n)] + [[0.01, 0.05], [0, 0.05], [0, 0]]
    elif shape == 1:  # collinear points
        pts = [[0, 0]] + [[0.01 * i / n, 0] for i in range(1, n)] + [[0.01, 0], [0, 0]]
    elif shape == 2:  # a tiny triangle
        e = pick(rng, [1e-12, 1e-300, 5e-324, 1e-9])
        pts = [[0, 0], [e, 0], [0, e], [0, 0]]
    else:  # a self-crossing bow tie
        pts = [[0, 0], [0.01, 0.01], [0.01, 0], [0, 0.01], [0, 0]]
    st.doc = set_at(st.doc, p, pts)
    return "profile %s: %s, %d points" % (pointer(p), ["sawtooth", "collinear", "tiny",
                                                       "bow tie"][shape], len(pts))


def m_array_edit(rng, st):
    c = nodes(st, lambda p, v: isinstance(v, list) and v, root_ok=True)
    if not c:
        return None
    p, v = pick(rng, c)
    op = rng.randrange(4)
    if op == 0:
        i = rng.randrange(len(v))
        v.insert(i, copy.deepcopy(v[i]))
        what = "element %d repeated" % i
    elif op == 1:
        v.reverse()
        what = "reversed"
    elif op == 2:
        n = pick(rng, [100, 10000])
        v.extend(copy.deepcopy(v[-1]) for _ in range(n))
        what = "last element repeated %d times" % n
    else:
        rng.shuffle(v)
        what = "shuffled"
    return "array %s %s" % (pointer(p), what)


JSON_MUTATIONS = [  # (weight, function)
    (12, m_number_extreme), (3, m_number_raw), (3, m_nan_string), (7, m_wrong_type),
    (6, m_delete_key), (2, m_delete_element), (4, m_unknown_key), (4, m_duplicate_key),
    (2, m_deep_nesting), (4, m_empty_container), (2, m_long_string), (3, m_change_format),
    (4, m_enum), (2, m_swap_kind), (3, m_path), (10, m_set_param), (4, m_scale),
    (2, m_big_profile), (3, m_array_edit),
]


# ---------------------------------------------------------------------------
# Byte mutations, on a file's text after it is written

def b_truncate(rng, data):
    if not data:
        return data, "truncated (empty already)"
    n = rng.randrange(len(data))
    return data[:n], "truncated to %d of %d bytes" % (n, len(data))


def b_nul(rng, data):
    n = rng.randrange(len(data) + 1)
    return data[:n] + b"\x00" + data[n:], "NUL byte at offset %d" % n


def b_invalid_utf8(rng, data):
    n = rng.randrange(len(data) + 1)
    junk = pick(rng, [b"\xff", b"\xc3", b"\xed\xa0\x80", b"\xef\xbb\xbf"])
    return data[:n] + junk + data[n:], "bytes %r at offset %d" % (junk, n)


def b_empty(rng, data):
    return b"", "empty file"


def b_bom(rng, data):
    return b"\xef\xbb\xbf" + data, "UTF-8 byte order mark prepended"


def b_trailing(rng, data):
    t = pick(rng, [b",", b"}", b"]", b"{}", b" x", b"// c", b"\n\n\n", b"\x1a"])
    return data.rstrip(b"\n") + t + b"\n", "trailing %r" % t


BYTE_MUTATIONS = [(6, b_truncate), (2, b_nul), (2, b_invalid_utf8), (1, b_empty), (1, b_bom),
                  (2, b_trailing)]


# ---------------------------------------------------------------------------
# CSV mutations, on a lab dataset's files

CSV_VALUES = ["abc", "nan", "NaN", "inf", "-inf", "1e300", "-1e300", "1e-300", "1e308", "1e309",
              "0", "-0", "-1", "", " 1", "1 ", "0x1A", "1.5.2", "1e", "e5", "+1", "2.0",
              "99999999999999999999999", "\uff11", "1e23", "100000.0000001", "5e-324",
              "-1e-300", "\"1\"", "1;2"]


def split_csv(text):
    """(lines, index of the header line or None)."""
    lines = text.split("\n")
    for i, line in enumerate(lines):
        s = line.strip()
        if s and not s.startswith("#"):
            return lines, i
    return lines, None


def parse_row(line):
    try:
        return next(csv.reader([line]), [])
    except csv.Error:  # a line an earlier mutation left unparseable (a lone CR, a NUL)
        return line.split(",")


def write_row(fields):
    buf = io.StringIO()
    csv.writer(buf, lineterminator="").writerow(fields)
    return buf.getvalue()


def data_rows(lines, h):
    return [i for i in range(h + 1, len(lines))
            if lines[i].strip() and not lines[i].startswith("#")]


def numeric_columns(lines, h):
    header = parse_row(lines[h])
    rows = [parse_row(lines[i]) for i in data_rows(lines, h)]
    out = []
    for j in range(len(header)):
        vals = [r[j] for r in rows if j < len(r) and r[j] != ""]
        try:
            [float(x) for x in vals]
            if vals:
                out.append(j)
        except ValueError:
            pass
    return out


def c_cell(rng, name, text):
    lines, h = split_csv(text)
    if h is None or not data_rows(lines, h):
        return None
    rows = data_rows(lines, h)
    i = pick(rng, rows)
    fields = parse_row(lines[i])
    num = numeric_columns(lines, h)
    cols = num if num and rng.random() < 0.75 else list(range(len(fields)))
    cols = [j for j in cols if j < len(fields)]
    if not cols:
        return None
    j = pick(rng, cols)
    old = fields[j]
    fields[j] = pick(rng, CSV_VALUES)
    lines[i] = write_row(fields)
    header = parse_row(lines[h])
    return "\n".join(lines), "%s line %d column %s: %r -> %r" % (
        name, i + 1, header[j] if j < len(header) else j, old, fields[j])


def c_column(rng, name, text):
    lines, h = split_csv(text)
    if h is None:
        return None
    header = parse_row(lines[h])
    rows = data_rows(lines, h)
    op = rng.randrange(3)
    if op == 0 and header:  # a column dropped
        j = rng.randrange(len(header))
        what = "column %s dropped" % header[j]
        for i in [h] + rows:
            f = parse_row(lines[i])
            if j < len(f):
                del f[j]
            lines[i] = write_row(f)
    elif op == 1:  # an extra column, unknown or a second copy of a known one
        col = pick(rng, ["fuzz", "Time", "note", "source"] + header)
        what = "extra column %s" % col
        for i in [h] + rows:
            f = parse_row(lines[i])
            f.append(col if i == h else pick(rng, ["1", "x", ""]))
            lines[i] = write_row(f)
    else:  # header renamed to upper case
        if not header:
            return None
        j = rng.randrange(len(header))
        what = "column %s renamed %s" % (header[j], header[j].upper())
        header[j] = header[j].upper()
        lines[h] = write_row(header)
    return "\n".join(lines), "%s: %s" % (name, what)


def c_row(rng, name, text):
    lines, h = split_csv(text)
    if h is None or not data_rows(lines, h):
        return None
    rows = data_rows(lines, h)
    i = pick(rng, rows)
    f = parse_row(lines[i])
    op = rng.randrange(5)
    if op == 0 and f:
        f.pop()
        lines[i] = write_row(f)
        what = "line %d one field short" % (i + 1)
    elif op == 1:
        f.append("1")
        lines[i] = write_row(f)
        what = "line %d one field long" % (i + 1)
    elif op == 2:
        lines.insert(i + 1, lines[i])
        what = "line %d repeated" % (i + 1)
    elif op == 3:
        lines[i] = '"' + lines[i]
        what = "line %d opens a quote it never closes" % (i + 1)
    else:
        lines[i] = ""
        lines.insert(i, "")
        what = "line %d blanked" % (i + 1)
    return "\n".join(lines), "%s: %s" % (name, what)


# The most text one mutation writes into a file. A long field (c_long_field:
# 1e6 characters) repeated over 200 000 rows would be 200 GB, beyond the
# address space this script shares with vahf (--memory-mb); 256 MiB is still
# far above any lab file (seed 1: mutants 1740 and 27770 of 0-39 999 reach it).
MAX_MUTANT_BYTES = 256 << 20


def c_many_rows(rng, name, text):
    """Many rows: a big file (repetition numbers kept distinct where the file has them)."""
    lines, h = split_csv(text)
    if h is None or not data_rows(lines, h):
        return None
    header = parse_row(lines[h])
    rows = [parse_row(lines[i]) for i in data_rows(lines, h)]
    n = rng.choices([1000, 20000, 200000], [5, 3, 1])[0]
    out = lines[:h + 1]
    rep = header.index("repetition") if "repetition" in header else None
    tcol = header.index("time") if name.startswith("tracks") and "time" in header else None
    size, capped = 0, False
    for k in range(n):
        f = list(rows[k % len(rows)])
        if rep is not None and rep < len(f):
            f[rep] = str(k + 1)
        if tcol is not None and tcol < len(f):
            f[tcol] = repr(k * 0.001)
        out.append(write_row(f))
        size += len(out[-1]) + 1
        if size > MAX_MUTANT_BYTES:  # rows made long by an earlier mutation
            n, capped = k + 1, True
            break
    return "\n".join(out) + "\n", "%s: %d rows%s" % (
        name, n, " (capped at %d MiB)" % (MAX_MUTANT_BYTES >> 20) if capped else "")


def c_long_field(rng, name, text):
    lines, h = split_csv(text)
    if h is None or not data_rows(lines, h):
        return None
    i = pick(rng, data_rows(lines, h))
    f = parse_row(lines[i])
    if not f:
        return None
    j = rng.randrange(len(f))
    n = pick(rng, [10000, 1000000])
    f[j] = pick(rng, ["x", "1", ","]) * n
    lines[i] = write_row(f)
    return "\n".join(lines), "%s line %d field %d of %d chars" % (name, i + 1, j, n)


def c_shape(rng, name, text):
    op = rng.randrange(6)
    lines, h = split_csv(text)
    if op == 0:
        return "", "%s: empty file" % name
    if op == 1 and h is not None:
        return "\n".join(lines[:h + 1]) + "\n", "%s: header only" % name
    if op == 2:
        return "# only a comment\n\n", "%s: comments only" % name
    if op == 3:
        return text.replace("\n", "\r\n"), "%s: CRLF line ends" % name
    if op == 4:
        return text.replace("\n", "\r"), "%s: CR line ends" % name
    return "\ufeff" + text, "%s: byte order mark" % name


def c_swap(rng, name, text, bases):
    other = pick(rng, [t for t in bases.csv_texts if t != text] + [
        to_text(pick(rng, [d for _, d in bases.all_docs]))])
    return other, "%s: replaced by another file's content (%s)" % (
        name, other.split("\n", 1)[0][:50])


# ---------------------------------------------------------------------------
# Mutant generation

CLASS_WEIGHTS = [("scene", 50), ("experiment", 18), ("lab", 20), ("generator", 4),
                 ("overrides", 4), ("cli", 4)]


def choose(rng, weighted):
    return rng.choices([f for _, f in weighted], [w for w, _ in weighted])[0]


def n_mutations(rng):
    return rng.choices([1, 2, 3], [55, 30, 15])[0]


def mutate_json(rng, st, k):
    """k mutations: a swap of the whole file first, byte mutations last (on the text)."""
    picks = [None if rng.random() < 0.12 else choose(rng, JSON_MUTATIONS) for _ in range(k)]
    picks.sort(key=lambda f: 0 if f is m_swap_kind else 2 if f is None else 1)
    desc = []
    for f in picks:
        if f is None:
            st.byte_ops.append(choose(rng, BYTE_MUTATIONS))  # described when applied
            continue
        for _ in range(20):  # another draw when one does not apply here
            d = f(rng, st)
            if d:
                desc.append(d)
                break
            f = choose(rng, JSON_MUTATIONS)
    return desc


def serialize(rng, st, desc):
    data = to_text(st.doc).encode("utf-8", "surrogatepass")
    out = [d for d in desc if d]
    for op in st.byte_ops:
        data, d = op(rng, data)
        out.append(d)
    return data, out


class Mutant:
    __slots__ = ("idx", "cls", "base", "mutations", "main", "files", "runs", "dir")

    def __init__(self, idx, cls, base):
        self.idx, self.cls, self.base = idx, cls, base
        self.mutations, self.files, self.runs = [], {}, []
        self.main = self.dir = None


def trial_variants(rng):
    runs = [["--seed", "1"]]
    r = rng.random()
    if r < 0.15:
        runs.append(["--seed", "1", "--integrator", pick(rng, INTEGRATORS)])
    elif r < 0.20:
        runs.append(["--seed", "1", "--position", str(pick(rng, [1, 2]))])
    elif r < 0.25:
        runs.append(["--seed", "1", "--trial", str(pick(rng, [7, 2 ** 64 - 1]))])
    return runs


CLI_VALUES = {
    "--seed": ["-1", "1e23", "18446744073709551616", "18446744073709551615", "0x10", "", " 1",
               "1.5", "nan", "+1", "01"],
    "--trial": ["-1", "18446744073709551615", "1e3", "x"],
    "--position": ["-1", "1", "2147483648", "1e9", "nan", ""],
    "--integrator": INTEGRATORS + ["", "rungekuttamerson", "Euler"],
    "--accuracy": ["nan", "1", "0", "1e-300", "-0", "0.99999999", "1e-16", "inf", "0x0.1", ""],
    "--sample": ["0", "-1", "nan", "1e-300", "1e-7", "inf", "1e300"],
    # traces stay inside the output tree (vahf runs there): a folder, a missing one, ""
    "--trace": ["{tree}", "{tree}/nonexistent/t.csv", "", "TRACE"],
}


# The trials' work budget on the command line as well as in the bases
# (--max-steps): a mutation that deletes a base's "simulation" object must not
# give its trial vahf's default budget of 1e6 steps, minutes on a stiff scene.
BUDGET = []


def make_mutant(idx, seed, bases):
    rng = random.Random(seed * 1000003 + idx)
    cls = choose(rng, [(w, c) for c, w in CLASS_WEIGHTS])
    name = "m%06d" % idx
    if cls == "scene":
        base = pick(rng, sorted(bases.scenes))
        m = Mutant(idx, cls, "experiments/" + base)
        st = State(cls, copy.deepcopy(bases.scenes[base]), bases, name + ".json")
        data, m.mutations = serialize(rng, st, mutate_json(rng, st, n_mutations(rng)))
        m.main = "experiments/%s.json" % name
        m.files[m.main] = data
        m.runs = [["check", "{main}"]] + [["trial", "{main}"] + v + BUDGET
                                          for v in trial_variants(rng)]
    elif cls in ("experiment", "generator", "overrides"):
        if cls == "experiment":
            base = pick(rng, sorted(bases.experiments))
            doc, folder, bname = bases.experiments[base], "experiments", "experiments/" + base
        elif cls == "generator":
            base = pick(rng, sorted(bases.generators))
            d, doc = bases.generators[base]
            folder, bname = "data/" + d, base
        else:
            doc, folder, bname = BUILTIN_OVERRIDES, "experiments", "built-in override file"
        m = Mutant(idx, cls, bname)
        st = State(cls, copy.deepcopy(doc), bases, name + ".json")
        data, m.mutations = serialize(rng, st, mutate_json(rng, st, n_mutations(rng)))
        m.main = "%s/%s.json" % (folder, name)
        m.files[m.main] = data
        m.runs = [["check", "{main}"]]
    elif cls == "lab":
        base = pick(rng, sorted(bases.labs))
        m = Mutant(idx, cls, base)
        files = {k: v.encode("utf-8") for k, v in bases.labs[base].items()}
        k = n_mutations(rng)
        for _ in range(k):
            csvs = sorted(f for f in files if f.endswith(".csv"))
            if csvs and rng.random() < 0.6:
                f = pick(rng, csvs)
                text = files[f].decode("utf-8", "surrogateescape")
                op = rng.choices(["cell", "column", "row", "many", "long", "shape", "swap",
                                  "bytes"], [10, 4, 5, 1, 1, 2, 1, 3])[0]
                if op == "bytes":
                    data, d = choose(rng, BYTE_MUTATIONS)(rng, files[f])
                    files[f], d = data, "%s: %s" % (f, d)
                else:
                    fn = {"cell": c_cell, "column": c_column, "row": c_row, "many": c_many_rows,
                          "long": c_long_field, "shape": c_shape}.get(op)
                    r = fn(rng, f, text) if fn else c_swap(rng, f, text, bases)
                    if not r:
                        continue
                    files[f] = r[0].encode("utf-8", "surrogateescape")
                    d = r[1]
                m.mutations.append(d)
            else:
                try:
                    doc = json.loads(files["dataset.json"])
                except (ValueError, RecursionError):
                    continue  # already garbled or nested too deep for Python: leave it
                st = State(cls, doc, bases, "dataset.json")
                data, ds = serialize(rng, st, mutate_json(rng, st, 1))
                files["dataset.json"] = data
                m.mutations += ["dataset.json: " + d for d in ds]
        folder = "data/%s" % name
        for f, data in files.items():
            m.files["%s/%s" % (folder, f)] = data
        m.main = folder + "/dataset.json"
        m.dir = folder
        m.runs = [["check", "{main}"]]
    else:  # cli: a shipped fast scene, a bad command line
        base = pick(rng, ["scenes/peg_in_hole.json", "scenes/free_move.json"])
        m = Mutant(idx, cls, "experiments/" + base)
        m.main = "experiments/%s.json" % name
        m.files[m.main] = to_text(bases.scenes[base]).encode()
        args = ["--seed", "1"]
        for _ in range(n_mutations(rng)):
            opt = pick(rng, sorted(CLI_VALUES))
            val = pick(rng, CLI_VALUES[opt])
            if opt == "--trace" and val == "TRACE":
                val = "{tree}/data/%s.trace.csv" % name
            if opt == "--sample" and "--trace" not in args:
                args += ["--trace", "{tree}/data/%s.trace.csv" % name]
            if opt in args:
                args[args.index(opt) + 1] = val
            else:
                args += [opt, val]
            m.mutations.append("option %s %r" % (opt, val))
        m.runs = [["trial", "{main}"] + args + BUDGET]
    if not m.mutations:
        m.mutations = ["(none applied: the base as is)"]
    return m


# ---------------------------------------------------------------------------
# Running

class Outcome:
    __slots__ = ("argv", "rc", "signal", "timeout", "stdout", "stderr", "seconds", "problem")


def run_one(vahf, argv, timeout, cwd):
    """Runs vahf with `timeout` seconds of CPU. A hang is judged on CPU time, so
    that a loaded machine cannot turn a slow but bounded run into one:
    RLIMIT_CPU, set by util-linux's prlimit (preexec_fn is unsafe under
    threads), sends SIGXCPU at the limit and SIGKILL 5 s later. The wall
    limit catches a process that hangs without using CPU."""
    o = Outcome()
    o.argv = [vahf] + argv
    o.signal = None
    o.timeout = False
    cpu = max(1, math.ceil(timeout))
    t0 = time.monotonic()
    try:
        p = subprocess.run(["prlimit", "--cpu=%d:%d" % (cpu, cpu + 5), "--"] + o.argv,
                           stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                           stderr=subprocess.PIPE, timeout=4 * cpu + 60, cwd=cwd)
        o.rc, o.stdout, o.stderr = p.returncode, p.stdout, p.stderr
    except subprocess.TimeoutExpired as e:
        o.rc, o.timeout = None, True
        o.stdout, o.stderr = e.stdout or b"", e.stderr or b""
    o.seconds = time.monotonic() - t0
    if o.rc in (-signal.SIGXCPU, -signal.SIGKILL):  # over the CPU limit
        o.rc, o.timeout = None, True
    if o.rc is not None and o.rc < 0:
        o.signal = -o.rc
    o.problem = problem_of(o)
    return o


def problem_of(o):
    if o.timeout:
        return "timeout"
    if o.signal:
        return "signal"
    if o.rc not in (0, 1, 2):
        return "exit"
    if o.rc == 2:
        err = o.stderr.decode("utf-8", "replace")
        body = err[:-1] if err.endswith("\n") else err
        if not body.startswith(ERROR_PREFIX) or "\n" in body:
            return "multiline"
    return None


def is_valid_scene(o):
    lines = o.stdout.decode("utf-8", "replace").rstrip("\n").split("\n")
    return o.rc == 0 and lines[-1].endswith(": valid scene")


def run_mutant(m, vahf, tree, timeout):
    out = []
    for i, argv in enumerate(m.runs):
        if i > 0 and out[0].rc != 0:
            break  # trial only on what check accepts
        argv = [a.replace("{main}", os.path.join(tree, m.main)).replace("{tree}", tree)
                for a in argv]
        out.append(run_one(vahf, argv, timeout, tree))
    return out


NUM = re.compile(r"(?<![A-Za-z_])[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|\b(?:nan|inf)\b",
                 re.I)


def mask(line, tree):
    line = line.replace(tree, "<tree>").replace(REPO, "<repo>")
    line = re.sub(r"m\d{6}", "M", line)
    line = re.sub(r'"(?:[^"\\]|\\.){24,}"', '"S"', line)
    line = NUM.sub("N", line)
    return line[:200]


def crash_text(err):
    """The line that says why a process aborted: an assertion, an exception, a sanitizer."""
    lines = [x for x in err.split("\n") if x.strip()]
    for pat in ("Assertion", "terminate called", "what()", "ERROR: AddressSanitizer",
                "runtime error", "Error detected", "SimTK Exception", "Aborted"):
        for x in lines:
            if pat in x:
                return x.strip()
    return lines[-1].strip() if lines else "(no stderr)"


def signature(o, tree):
    cmd = o.argv[1]
    if "--integrator" in o.argv:
        cmd += " --integrator " + o.argv[o.argv.index("--integrator") + 1]
    err = o.stderr.decode("utf-8", "replace")
    if o.timeout:
        return "%s: timeout" % cmd
    if o.signal:
        try:
            name = signal.Signals(o.signal).name
        except ValueError:
            name = "signal %d" % o.signal
        return "%s: %s: %s" % (cmd, name, mask(crash_text(err), tree))
    first = err.split("\n", 1)[0]
    if o.problem == "exit":
        return "%s: exit %d: %s" % (cmd, o.rc, mask(first, tree))
    if o.problem == "multiline":
        n = err.rstrip("\n").count("\n") + 1 if err else 0
        return "%s: exit 2, %d-line stderr: %s" % (cmd, n, mask(first, tree))
    return "%s: exit %s: %s" % (cmd, o.rc, mask(first, tree))


def shell_quote(a):
    return a if re.fullmatch(r"[\w@%+=:,./-]+", a) else "'" + a.replace("'", "'\\''") + "'"


def keep_failure(out_dir, tree, m, o, kind):
    d = os.path.join(out_dir, "failures", "%06d-%s-%s-%s" % (m.idx, m.cls, o.argv[1], kind))
    os.makedirs(d, exist_ok=True)
    for f in m.files:  # the mutant's files, also left in the tree
        dst = os.path.join(d, "files", os.path.relpath(f, m.dir) if m.dir else
                           os.path.basename(f))
        os.makedirs(os.path.dirname(dst), exist_ok=True)
        shutil.copyfile(os.path.join(tree, f), dst)
    with open(os.path.join(d, "cmd.sh"), "w") as f:
        f.write("#!/bin/sh\n# mutant %d (%s) of %s; the file stays in %s, where its relative "
                "paths resolve\n" % (m.idx, m.cls, m.base, tree))
        f.write("cd %s && %s\n" % (shell_quote(tree), " ".join(shell_quote(a) for a in o.argv)))
    with open(os.path.join(d, "mutation.txt"), "w") as f:
        f.write("base: %s\n" % m.base + "".join("mutation: %s\n" % x for x in m.mutations))
        f.write("result: %s\n" % ("timeout" if o.timeout else "signal %d" % o.signal
                                  if o.signal else "exit %d" % o.rc))
    with open(os.path.join(d, "stderr.txt"), "wb") as f:
        f.write(o.stderr)
    with open(os.path.join(d, "stdout.txt"), "wb") as f:
        f.write(o.stdout[:100000])
    return d


def backtrace(argv, cwd, frames=8):
    """gdb's backtrace of a crashing run: its top frames above libc's abort, or None."""
    gdb = shutil.which("gdb")
    if not gdb:
        return None
    try:
        p = subprocess.run([gdb, "-batch", "-nx", "-ex", "run", "-ex", "bt"] + ["--args"] + argv,
                           stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, timeout=300, cwd=cwd)
    except subprocess.TimeoutExpired:
        return None
    text = p.stdout.decode("utf-8", "replace")
    bt = [x for x in text.split("\n") if re.match(r"#\d+ ", x)]
    libc = re.compile(r"__pthread_kill|__GI_raise|__GI_abort| raise \(| abort \(|"
                      r"__assert_fail|__libc_message")
    while bt and libc.search(bt[0]):  # from the first frame above the C library's abort
        bt.pop(0)
    return bt[:frames] if bt else None


def prepare_out(out):
    if os.path.exists(out):
        entries = os.listdir(out)
        if entries and OUT_MARKER not in entries:
            sys.exit("fuzz_inputs.py: --out %s exists and is not a fuzz output folder (no %s); "
                     "refusing to clear it" % (out, OUT_MARKER))
        for e in entries:
            p = os.path.join(out, e)
            if os.path.isdir(p) and not os.path.islink(p):
                shutil.rmtree(p)
            else:
                os.remove(p)
    os.makedirs(out, exist_ok=True)
    open(os.path.join(out, OUT_MARKER), "w").close()
    tree = os.path.join(out, "tree")
    shutil.copytree(os.path.join(REPO, "experiments"), os.path.join(tree, "experiments"))
    shutil.copytree(os.path.join(REPO, "data"), os.path.join(tree, "data"))
    return tree


def limit_memory(mb):
    if resource and mb > 0:
        soft, hard = resource.getrlimit(resource.RLIMIT_AS)
        lim = mb * 1024 * 1024
        if hard != resource.RLIM_INFINITY:
            lim = min(lim, hard)
        resource.setrlimit(resource.RLIMIT_AS, (lim, hard))


def env_int(name, default):
    v = os.environ.get(name)
    if v is None or v == "":
        return default
    if not re.fullmatch(r"\d+", v):
        sys.exit("fuzz_inputs.py: %s=%r is not a non-negative integer" % (name, v))
    return int(v)


def main(argv=None):
    ap = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0] + " Mutates the repository's scene, experiment, "
        "lab, generator and override files with a seeded generator, runs `vahf check` (and "
        "`vahf trial` on accepted scenes) on each, and fails on a signal, a timeout, an exit "
        "status outside {0, 1, 2} or an exit-2 message that is not one 'vahf: error: ' line.",
        epilog="Exit status: 0 no failure, 1 a failure, 2 bad usage. Environment: "
        "VAHF_FUZZ_FILES, VAHF_FUZZ_SEED set the defaults of --files and --seed. "
        "Example: VAHF_FUZZ_FILES=20000 %(prog)s --vahf build/ci/tools/vahf --jobs 2 "
        "--out /tmp/fuzz. The header of this file lists the bases and mutations.")
    ap.add_argument("--vahf", default=os.path.join(REPO, "build", "ci", "tools", "vahf"),
                    help="the vahf executable (default: %(default)s)")
    ap.add_argument("--files", type=int, default=env_int("VAHF_FUZZ_FILES", DEFAULT_FILES),
                    help="mutants to make and run (default: $VAHF_FUZZ_FILES or %d, the CI "
                    "size)" % DEFAULT_FILES)
    ap.add_argument("--seed", type=int, default=env_int("VAHF_FUZZ_SEED", DEFAULT_SEED),
                    help="generator seed (default: $VAHF_FUZZ_SEED or %d)" % DEFAULT_SEED)
    ap.add_argument("--first", type=int, default=0,
                    help="index of the first mutant (default 0): mutants FIRST..FIRST+FILES-1")
    ap.add_argument("--only", metavar="I[,J...]",
                    help="make and run these mutants alone (reproduces failures: their "
                    "numbers are in OUT/summary.json)")
    ap.add_argument("--out", help="output folder: the mutants' tree, failures/, summary.json "
                    "(default: a new folder under $TMPDIR); an existing one is cleared only if "
                    "an earlier run of this script made it")
    ap.add_argument("--timeout", type=float, default=120.0,
                    help="seconds of CPU per vahf process before it counts as hung, or 4x "
                    "that plus 60 s of wall (default 120: a trial's 20 000-step budget takes "
                    "77-82 s of CPU on seed 1 mutant 46634, a peg starting 29 mm inside a "
                    "stiff wall; the contact test budget ends mutant 48454's wedged sawtooth "
                    "peg, 133 s under the step budget alone, after about 14 s: "
                    "tests/fuzz/FINDINGS.md)")
    ap.add_argument("--jobs", type=int, default=1,
                    help="vahf processes run at once (default 1); results do not depend on it")
    ap.add_argument("--time-limit", type=float, default=1.0,
                    help="simulation/time_limit (s) written into every scene base before it is "
                    "mutated, to keep trials short (default 1: every base scene completes its "
                    "first part within 0.86 s; 0 keeps the scenes' own)")
    ap.add_argument("--max-steps", type=int, default=20000,
                    help="simulation/max_steps written into every scene base, the trials' work "
                    "budget (default 20000: the costliest base scene takes 16 000 steps for its "
                    "first part; 0 keeps vahf's default)")
    ap.add_argument("--max-contact-tests", type=float, default=2e9,
                    help="simulation/max_contact_tests set on every trial's command line, the "
                    "other half of its work budget: a step's cost grows with the points in "
                    "contact and a profile's vertices (default 2e9; vahf's is 3e10; "
                    "0 keeps the scene's)")
    ap.add_argument("--memory-mb", type=int, default=4096,
                    help="address-space limit of each vahf process, MiB (default 4096; 0 none)")
    ap.add_argument("--strict-check", action="store_true",
                    help="count 'check accepts what trial rejects' cases, and any exit 1 of "
                    "`vahf check`, as failures (tools/test runs with it)")
    ap.add_argument("--keep-all", action="store_true",
                    help="keep every mutant in OUT/tree, not only the failing ones")
    ap.add_argument("--list", action="store_true",
                    help="print each mutant's class, base and mutations; run nothing")
    ap.add_argument("--backtrace", action="store_true",
                    help="for each group of crashes (signals), run its first reproducer under "
                    "gdb and report the backtrace's top frames (bt.txt in its failure folder)")
    ap.add_argument("--quiet", action="store_true", help="no progress lines")
    a = ap.parse_args(argv)
    if (a.files < 0 or a.jobs < 1 or a.timeout <= 0 or a.seed < 0 or a.first < 0 or
            not a.max_contact_tests >= 0):
        ap.error("--files, --seed, --first, --max-contact-tests >= 0; --jobs >= 1; --timeout > 0")
    if a.only is not None and not re.fullmatch(r"\d+(,\d+)*", a.only):
        ap.error("--only takes mutant numbers separated by commas, not %r" % a.only)

    bases = Bases(a.time_limit, a.max_steps)
    BUDGET[:] = []
    if a.max_steps > 0:
        BUDGET.extend(["--set", "simulation/max_steps=%d" % a.max_steps])
    # On the command line only: written into the bases it would change every
    # mutant drawn from them, and earlier soaks' mutant numbers with them.
    if a.max_contact_tests > 0:
        BUDGET.extend(["--set", "simulation/max_contact_tests=%.17g" % a.max_contact_tests])
    indices = ([int(x) for x in a.only.split(",")] if a.only is not None else
               list(range(a.first, a.first + a.files)))

    if a.list:
        for i in indices:
            m = make_mutant(i, a.seed, bases)
            print("%06d %-10s %s: %s" % (i, m.cls, m.base, "; ".join(m.mutations)))
        return 0

    vahf = os.path.abspath(a.vahf)
    if not (os.path.isfile(vahf) and os.access(vahf, os.X_OK)):
        ap.error("--vahf %s is not an executable" % vahf)
    out = os.path.abspath(a.out) if a.out else tempfile.mkdtemp(prefix="vahf_fuzz.")
    tree = prepare_out(out)
    limit_memory(a.memory_mb)

    t0 = time.monotonic()
    mutants = []
    for i in indices:  # all generated and written, in order, before any run
        m = make_mutant(i, a.seed, bases)
        for f, data in m.files.items():
            p = os.path.join(tree, f)
            os.makedirs(os.path.dirname(p), exist_ok=True)
            with open(p, "wb") as fh:
                fh.write(data)
        # Only the names stay in memory: the data are on disk, and a run of
        # 100 000 mutants (lab CSVs of up to 200 000 rows among them) would
        # otherwise exceed the address-space limit this process shares
        # with its children (--memory-mb).
        m.files = dict.fromkeys(m.files)
        mutants.append(m)
    t_gen = time.monotonic() - t0
    if not a.quiet:
        print("fuzz_inputs.py: %d mutants (seed %d) written to %s in %.1f s; running %s with "
              "%d job(s)" % (len(mutants), a.seed, tree, t_gen, vahf, a.jobs), flush=True)

    results = [None] * len(mutants)
    done = [0]
    lock = threading.Lock()

    def work(k):
        r = run_mutant(mutants[k], vahf, tree, a.timeout)
        for o in r:  # keep what the tally needs; failures keep everything
            if not o.problem:
                o.stdout = o.stdout[-300:]
                o.stderr = o.stderr[:2000]
        with lock:
            done[0] += 1
            if not a.quiet and done[0] % 500 == 0:
                print("  %d/%d mutants, %.0f s" % (done[0], len(mutants),
                                                   time.monotonic() - t0), flush=True)
        return k, r

    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as ex:
        for k, r in ex.map(work, range(len(mutants))):
            results[k] = r
    wall = time.monotonic() - t0

    # ---- tally, in mutant order
    classes = [c for c, _ in CLASS_WEIGHTS]
    stats = {c: {"files": 0, "runs": 0, "exit": {}, "signals": 0, "timeouts": 0,
                 "bad_exit": 0, "multiline": 0, "catr": 0, "seconds": 0.0} for c in classes}
    seconds = {}  # per command: check, trial, trial --integrator
    failures, catr, exit1, noise, ended = [], [], {}, {}, {}
    for m, runs in zip(mutants, results):
        s = stats[m.cls]
        s["files"] += 1
        failed = False
        for j, o in enumerate(runs):
            s["runs"] += 1
            s["seconds"] += o.seconds
            cmd = o.argv[1] + (" --integrator" if "--integrator" in o.argv else "")
            seconds.setdefault(cmd, [0, 0.0])
            seconds[cmd][0] += 1
            seconds[cmd][1] += o.seconds
            key = "timeout" if o.timeout else ("sig%d" % o.signal if o.signal else str(o.rc))
            s["exit"][key] = s["exit"].get(key, 0) + 1
            if o.problem:
                s[{"timeout": "timeouts", "signal": "signals", "exit": "bad_exit",
                   "multiline": "multiline"}[o.problem]] += 1
                failures.append((m, o, o.problem))
                failed = True
            elif o.rc in (0, 1):
                err = o.stderr.decode("utf-8", "replace").split("\n")
                own = [x for x in err if x.startswith("vahf: ")]
                if o.rc == 1:
                    last = own[-1] if own else ""
                    t = re.match(r"vahf: trial ended (\w+)", last)
                    if t:
                        ended[t.group(1)] = ended.get(t.group(1), 0) + 1
                    else:
                        sig = "%s: exit 1: %s" % (o.argv[1], mask(last or "(no vahf: line)",
                                                                  tree))
                        exit1.setdefault(sig, [0, m, o])[0] += 1
                        # check computes nothing: its exit 1 is bad input
                        # that escaped the rules (bad input wants exit 2).
                        if a.strict_check and o.argv[1] == "check":
                            failures.append((m, o, "check-exit-1"))
                            failed = True
                other = [x for x in err if x.strip() and not x.startswith("vahf: ")]
                if other:
                    sig = "%s: exit %d: %s" % (o.argv[1], o.rc, mask(other[0].strip(), tree))
                    noise.setdefault(sig, [0, m, o])[0] += 1
            if (j > 0 and o.argv[1] == "trial" and o.rc == 2 and runs[0].argv[1] == "check"
                    and "--position" not in o.argv and is_valid_scene(runs[0])):
                s["catr"] += 1
                catr.append((m, o))
                if a.strict_check:
                    failures.append((m, o, "check-accepts-trial-rejects"))
                    failed = True
        if not failed and not a.keep_all:
            for f in m.files:
                try:
                    os.remove(os.path.join(tree, f))
                except OSError:
                    pass
            if m.dir:
                shutil.rmtree(os.path.join(tree, m.dir), ignore_errors=True)
    for suffix in (".trace.csv", ".trace.csv.partial"):  # a killed run leaves .partial
        for m in mutants:
            p = os.path.join(tree, "data", "m%06d%s" % (m.idx, suffix))
            if os.path.exists(p):
                os.remove(p)

    groups = {}
    for m, o, kind in failures:
        sig = signature(o, tree) if kind != "check-accepts-trial-rejects" else \
            "check accepts, trial rejects: " + mask(o.stderr.decode("utf-8", "replace")
                                                    .split("\n", 1)[0], tree)
        g = groups.setdefault(sig, {"count": 0, "kind": kind, "dirs": []})
        g["count"] += 1
        if len(g["dirs"]) < 3:
            g["dirs"].append(keep_failure(out, tree, m, o, kind))
        if a.backtrace and kind == "signal" and "bt" not in g:
            g["bt"] = backtrace(o.argv, tree)
            if g["bt"]:
                with open(os.path.join(g["dirs"][0], "bt.txt"), "w") as f:
                    f.write("\n".join(g["bt"]) + "\n")
        g.setdefault("mutations", m.mutations)
        g.setdefault("base", m.base)
        g.setdefault("idx", m.idx)
    catr_rules = {}
    for m, o in catr:
        sig = mask(o.stderr.decode("utf-8", "replace").split("\n", 1)[0], tree)
        catr_rules.setdefault(sig, []).append(m)

    # ---- report
    nfiles = len(mutants)
    cpu = (resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime +
           resource.getrusage(resource.RUSAGE_CHILDREN).ru_stime) if resource else float("nan")
    print("fuzz_inputs.py: seed %d, %d files, %d runs, %.1f s wall with %d job(s) "
          "(%.1f s per 1000 files), %.1f s CPU in vahf; vahf %s" % (
              a.seed, nfiles, sum(len(r) for r in results), wall, a.jobs,
              1000 * wall / max(1, nfiles), cpu, vahf))
    for c in classes:
        s = stats[c]
        if not s["files"]:
            continue
        ex = ", ".join("%s %d" % (k, v) for k, v in sorted(s["exit"].items()))
        print("  %-10s %5d files %5d runs  exit: %s; signals %d, timeouts %d, other exit %d, "
              "multi-line errors %d, check-accepts-trial-rejects %d; %.0f s in vahf" % (
                  c, s["files"], s["runs"], ex, s["signals"], s["timeouts"], s["bad_exit"],
                  s["multiline"], s["catr"], s["seconds"]))
    print("  time in vahf: " + "; ".join("%s %d runs %.1f s (%.3f s each)" % (
        k, n, t, t / n) for k, (n, t) in sorted(seconds.items())))
    print("check accepts what trial rejects: %d case(s) under %d rule(s)%s" % (
        len(catr), len(catr_rules), " (failures: --strict-check)" if a.strict_check else
        " (recorded, not failures; --strict-check makes them failures)"))
    for sig, ms in sorted(catr_rules.items(), key=lambda x: -len(x[1])):
        print("  %4d  %s\n        e.g. mutant %d (%s: %s)" % (
            len(ms), sig, ms[0].idx, ms[0].base, "; ".join(ms[0].mutations)[:300]))
    if exit1:
        print("exit 1 other than 'vahf: trial ended' (not failures): %d signature(s)" %
              len(exit1))
        for sig, (n, m, o) in sorted(exit1.items(), key=lambda x: -x[1][0]):
            print("  %4d  %s\n        e.g. mutant %d (%s: %s)" % (
                n, sig, m.idx, m.base, "; ".join(m.mutations)[:300]))
    if noise:
        print("stderr lines not from vahf on exit 0 or 1 (libraries' own output; not "
              "failures): %d signature(s)" % len(noise))
        for sig, (n, m, o) in sorted(noise.items(), key=lambda x: -x[1][0]):
            print("  %4d  %s\n        e.g. mutant %d (%s: %s)" % (
                n, sig, m.idx, m.base, "; ".join(m.mutations)[:300]))
    print("trials that ended other than completed (exit 1, not failures): " + (", ".join(
        "%s %d" % kv for kv in sorted(ended.items())) or "none"))
    slow = sorted(((o.seconds, m, o) for m, runs in zip(mutants, results) for o in runs
                   if not o.timeout), key=lambda x: -x[0])[:5]
    print("slowest runs that finished: " + "; ".join(
        "mutant %d %s %.1f s" % (m.idx, " ".join(o.argv[1:2] + o.argv[3:]), t)
        for t, m, o in slow))
    print("failures: %d in %d group(s)" % (len(failures), len(groups)))
    for sig, g in sorted(groups.items(), key=lambda x: -x[1]["count"]):
        print("  %4d  %s\n        e.g. mutant %d (%s: %s)\n        %s" % (
            g["count"], sig, g["idx"], g["base"], "; ".join(g["mutations"])[:300],
            g["dirs"][0]))
        for x in g.get("bt") or []:
            print("          " + x[:200])
    summary = {
        "seed": a.seed, "files": nfiles, "first": indices[0] if indices else 0,
        "jobs": a.jobs, "wall_s": wall, "cpu_s_in_vahf": cpu, "timeout_s": a.timeout,
        "time_limit_s": a.time_limit,
        "vahf": vahf, "classes": stats,
        "seconds_by_command": seconds,
        "failures": [{"signature": s, "count": g["count"], "kind": g["kind"],
                      "mutant": g["idx"], "base": g["base"], "mutations": g["mutations"],
                      "kept": g["dirs"], "backtrace": g.get("bt")}
                     for s, g in groups.items()],
        "check_accepts_trial_rejects": [{"rule": s, "count": len(ms),
                                         "mutants": [x.idx for x in ms[:20]],
                                         "mutations": ms[0].mutations}
                                        for s, ms in catr_rules.items()],
        "failure_list": [{"mutant": m.idx, "class": m.cls, "base": m.base,
                          "mutations": m.mutations, "kind": kind,
                          "command": " ".join(shell_quote(x) for x in o.argv),
                          "seconds": round(o.seconds, 3),
                          "signature": signature(o, tree)} for m, o, kind in failures],
        "exit1_other": [{"signature": s, "count": n, "mutant": m.idx,
                         "mutations": m.mutations} for s, (n, m, o) in exit1.items()],
        "stderr_noise": [{"signature": s, "count": n, "mutant": m.idx,
                          "mutations": m.mutations} for s, (n, m, o) in noise.items()],
        "trials_ended": ended,
    }
    with open(os.path.join(out, "summary.json"), "w") as f:
        json.dump(summary, f, indent=1)
    print("output: %s (summary.json, failures/)" % out)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

"""vahf in Python: the harness's library as a module (docs/python.md).

Every function calls the library the ``vahf`` command calls, so the same
inputs give the same bits: a run's results digest and CSV bytes are the
command's, on any thread count. Tables come back as pandas DataFrames read
from the CSV text the library wrote, so their values are the CSV's, bit for
bit.

Errors are the command's three tiers: ``InputError`` (bad input; ``file``,
``field``, ``value``, ``rule``), ``ComputationError`` and ``InternalError``
(a failed internal check: a bug, raised instead of ending the interpreter).
Long calls run on worker threads without the GIL; Ctrl-C stops them as it
stops the command (running trials finish, none starts) and raises
KeyboardInterrupt.

Build it with the command (``tools/build`` or CMake's release preset), then::

    PYTHONPATH=build/release/python /usr/bin/python3 -c "import vahf"
"""

from __future__ import annotations

import io
import json
import operator
import os
from typing import Any, Callable, Optional, Union

from . import _vahf
from ._errors import ComputationError, Error, InputError, InternalError
from ._vahf import Experiment, Scene

__all__ = [
    "ComputationError", "Error", "Experiment", "InputError", "InternalError",
    "Lab", "Run", "Scene", "TrialResult", "check", "load_experiment",
    "load_lab", "load_scene", "params", "read_csv", "replay", "run",
    "synthesize", "trial", "verify",
]

PathLike = Union[str, "os.PathLike[str]"]
# progress(label, unit, done, total), or True for tqdm
Progress = Union[None, bool, Callable[[str, str, int, int], Any]]


def read_csv(source: Any) -> Any:
    """A CSV file (a path, or its text as io.StringIO) as a DataFrame whose
    numbers are the text's, bit for bit (pandas' round-trip parser)."""
    import pandas
    return pandas.read_csv(source, float_precision="round_trip")


def _sets(values):
    """{"group/key": value} as (name, value) pairs; the library reads each
    value by its parameter's rule, as the command reads --set."""
    return [(str(name), value) for name, value in (values or {}).items()]


def _integer(name, value, low, high):
    """An integer argument read as the command reads its option: from
    ``low`` to ``high``, else an InputError naming it."""
    try:
        number = None if isinstance(value, bool) else operator.index(value)
    except TypeError:
        number = None
    if number is None or not low <= number <= high:
        rule = "must be an integer from %d to %d" % (low, high)
        raise InputError("%s = %r: %s" % (name, value, rule), name, "",
                         repr(value), rule)
    return number


def _threads(threads, default=None):
    """The worker threads as the command takes --threads: 1 to 1024."""
    if threads is None and default is not None:
        return default
    return _integer("threads", threads, 1, 1024)


_U64 = 2 ** 64 - 1


class _Tqdm:
    """A progress callback drawing one tqdm bar per batch of a run."""

    def __init__(self, tqdm):
        self._tqdm = tqdm
        self._bar = None
        self._label = None

    def __call__(self, label, unit, done, total):
        if self._bar is None or label != self._label or done < self._bar.n:
            self.close()
            self._bar = self._tqdm(total=total, desc=label, unit=unit)
            self._label = label
        self._bar.update(done - self._bar.n)

    def close(self):
        if self._bar is not None:
            self._bar.close()
            self._bar = None


def _progress(progress):
    """(callback or None, whether the library prints its own line)."""
    if progress is None or progress is False:
        return None, False
    if callable(progress):
        return progress, False
    try:
        from tqdm.auto import tqdm
    except ImportError:
        return None, True  # the command's progress line, on stderr
    return _Tqdm(tqdm), False


def _close(callback):
    if isinstance(callback, _Tqdm):
        callback.close()


def params() -> Any:
    """Every model parameter as a DataFrame: name (group/key), unit, rule,
    default and description (what ``vahf params`` prints)."""
    import pandas
    return pandas.DataFrame(
        _vahf.params(),
        columns=["name", "unit", "rule", "default", "description"])


def load_scene(path: PathLike, set: Optional[dict] = None) -> Scene:
    """Reads and validates a scene file, then applies ``set``:
    {"group/key": value} by each parameter's rule (``vahf params``).
    Raises InputError naming file, field, value and rule."""
    return _vahf.load_scene(os.fspath(path), _sets(set))


def load_experiment(path: PathLike,
                    overrides: Optional[PathLike] = None) -> Experiment:
    """Reads and validates an experiment file; ``overrides``: a parameter
    override file (vahf-overrides/1, e.g. a calibration's calibrated.json)
    applied to every scene it runs, as ``vahf run --overrides``."""
    return _vahf.load_experiment(
        os.fspath(path), os.fspath(overrides) if overrides else "")


class TrialResult:
    """One trial: every field of the command's summary (``summary`` is its
    text), ``counters``, ``warnings`` (kind -> count, first_time, detail),
    ``rests``, and ``trace``, a DataFrame with the trace CSV's columns
    (``trace_csv`` is its text, the bytes ``vahf trial --trace`` writes)."""

    status: str  # completed, timeout, exhausted, unreachable, jammed, ...
    detail: str  # why it ended
    part: str
    integrator: str
    accuracy: float
    seed: int
    trial: int
    end_time: float  # simulated s
    completion_time: float  # s; -1 unless completed
    first_contact_time: float  # s; -1 if never in contact
    work: float  # J (Eq. 4)
    max_penetration: float  # m
    penetration_bound: float  # m; 0 without a radial fit
    clearance: float  # m
    stiffness: float
    line_stiffness: float
    wall_seconds: float  # measured, never part of a digest
    cpu_seconds: float  # measured, never part of a digest
    counters: dict
    rests: dict
    warnings: dict
    warnings_summary: str
    summary: str  # the text vahf trial prints
    trace_csv: str  # "" when no trace was recorded
    trace_rows: int
    sample_rows: int

    def __init__(self, fields: dict):
        self.__dict__.update(fields)
        self._trace = None

    @property
    def trace(self) -> Any:
        """The trace as a DataFrame (read when first asked for: pandas is
        needed only then); None when the trial recorded none."""
        if self._trace is None and self.trace_csv:
            self._trace = read_csv(io.StringIO(self.trace_csv))
        return self._trace

    @property
    def completed(self):
        """Whether the trial ended ``completed``."""
        return self.status == "completed"

    def __repr__(self):
        return "<vahf.TrialResult %s %s seed %d trial %d: %s>" % (
            self.part, self.integrator, self.seed, self.trial, self.status)


def trial(scene: Union[PathLike, Scene], seed: int, trial: int = 0,
          position: Optional[int] = None, integrator: Optional[str] = None,
          set: Optional[dict] = None, sample: Optional[float] = None,
          trace: bool = True, progress: Progress = None) -> TrialResult:
    """One seeded trial, as ``vahf trial SCENE --seed SEED``.

    scene: a path or a Scene (load_scene); trial: the trial index (the
    stream key); position: which entry of the scene's sequence (0 first);
    integrator: overrides simulation/integrator; set: {"group/key": value};
    sample: with trace, also a row every ``sample`` s of simulated time;
    trace: record the trace (one row per decision instant).
    Returns a TrialResult; a trial that ends other than completed is a
    result (its ``status``), not an exception."""
    if not isinstance(scene, Scene):
        scene = load_scene(scene)
    # The integrator first, then the sets, as the command applies them.
    sets = ([("simulation/integrator", integrator)] if integrator else []) \
        + _sets(set)
    callback, _ = _progress(progress)
    try:
        fields = _vahf.trial(
            scene, _integer("seed", seed, 0, _U64),
            _integer("trial", trial, 0, _U64),
            _integer("position", position or 0, 0, 2 ** 31 - 1),
            "", sets, float(sample or 0), bool(trace), callback)
    finally:
        _close(callback)
    return TrialResult(fields)


def _claims(node, section, out):
    """Every claim record in summary.json, with the section it is in."""
    if isinstance(node, dict):
        for key, value in node.items():
            if key == "claims" and isinstance(value, list):
                for claim in value:
                    out.append(dict(claim, section=section))
            else:
                _claims(value, key if section is None else section, out)
    elif isinstance(node, list):
        for value in node:
            _claims(value, section, out)
    return out


class Run:
    """A run's output directory as read back: ``tables`` (CSV file name
    without .csv -> DataFrame), ``summary`` (summary.json), ``claims``
    (verdict, test, evidence, ...: one record each), ``manifest``
    (manifest.json), ``digest`` (its results digest), ``out``, ``report``
    (report.md's path) and ``status`` (the command's exit status: 1 when a
    plot could not be rendered)."""

    def __init__(self, out, status=0):
        self.out = out
        self.status = status
        with open(os.path.join(out, "manifest.json")) as f:
            self.manifest = json.load(f)
        summary = os.path.join(out, "summary.json")
        self.summary = {}
        if os.path.exists(summary):
            with open(summary) as f:
                self.summary = json.load(f)
        self.digest = self.manifest.get("results_digest")
        self.tables = {}
        for name in sorted(os.listdir(out)):
            if name.endswith(".csv"):
                self.tables[name[:-4]] = read_csv(os.path.join(out, name))
        self.claims = _claims(self.summary, None, [])
        self.report = os.path.join(out, "report.md")

    def claims_frame(self):
        """The claims as a DataFrame."""
        import pandas
        return pandas.DataFrame(self.claims)

    def __repr__(self):
        return "<vahf.Run %s: %d tables, digest %s>" % (
            self.out, len(self.tables), (self.digest or "")[:8])


def run(experiment: Union[PathLike, Experiment], seed: Optional[int] = None,
        threads: int = 1, out: Optional[PathLike] = None, resume: bool = False,
        trials: Optional[int] = None, overrides: Optional[PathLike] = None,
        progress: Progress = None) -> Run:
    """Runs an experiment as ``vahf run`` and reads its output back.

    experiment: a path or an Experiment (load_experiment); seed: overrides
    the file's; threads: worker threads (the results do not depend on it);
    out: the output directory (default runs/NAME-seedSEED, as the command);
    resume: continue a stopped run from its journal; trials: overrides the
    cycles per condition; overrides: a parameter override file (with a
    path); progress: a callable(label, unit, done, total) called on this
    thread, or True for tqdm (if installed; else the command's line).
    Returns a Run."""
    if not isinstance(experiment, Experiment):
        experiment = load_experiment(experiment, overrides)
    elif overrides:
        raise InputError(
            "overrides: give them to load_experiment", "overrides", "",
            str(overrides), "applies only to an experiment given by its path")
    callback, line = _progress(progress)
    try:
        done = _vahf.run(
            experiment,
            None if seed is None else _integer("seed", seed, 0, _U64),
            0 if trials is None else _integer("trials", trials, 1, 10 ** 7),
            _threads(threads), os.fspath(out) if out else "", bool(resume), line,
            callback)
    finally:
        _close(callback)
    return Run(done["out"], done["status"])


def check(path: PathLike) -> str:
    """Validates a scene, experiment, lab dataset, override or
    synthetic-lab file as ``vahf check`` does; returns what it prints."""
    return _vahf.check(os.fspath(path))


def verify(run_dir: PathLike, threads: Optional[int] = None,
           keep: Optional[PathLike] = None, progress: Progress = None) -> bool:
    """Re-runs a run from its manifest as ``vahf verify`` and compares
    every result file; True when every one is identical."""
    callback, _ = _progress(progress)
    try:
        return _vahf.verify(os.fspath(run_dir), _threads(threads, 0),
                            os.fspath(keep) if keep else "", callback) == 0
    finally:
        _close(callback)


def replay(run_dir: PathLike, cycle: str, trace: Optional[PathLike] = None,
           sample: Optional[float] = None) -> bool:
    """Runs one cycle of a run again as ``vahf replay RUN_DIR --cycle
    TABLE:ROW``; True when its rows are the table's, bit for bit."""
    return _vahf.replay(os.fspath(run_dir), cycle,
                        os.fspath(trace) if trace else "",
                        float(sample or 0)) == 0


class Lab:
    """A lab dataset: ``trials``, ``segments``, ``summaries`` (DataFrames,
    None when the dataset has no such table), ``tracks`` (file ->
    DataFrame), ``name``, ``description`` and ``text`` (what ``vahf check``
    says of it)."""

    def __init__(self, files):
        folder = files["folder"]

        def table(name):
            return read_csv(os.path.join(folder, name)) if name else None

        self.name = files["name"]
        self.description = files["description"]
        self.text = files["describe"]
        self.trials = table(files["trials"])
        self.segments = table(files["segments"])
        self.summaries = table(files["summaries"])
        self.tracks = {t: read_csv(t) for t in files["tracks"]}

    def __repr__(self):
        return "<vahf.Lab '%s'>" % self.name


def load_lab(path: PathLike) -> Lab:
    """Loads and validates a lab dataset (its dataset.json, or the folder
    holding it); returns a Lab."""
    path = os.fspath(path)
    if os.path.isdir(path):
        path = os.path.join(path, "dataset.json")
    return Lab(_vahf.lab_files(path))


def synthesize(generator: PathLike, out: PathLike, threads: int = 1,
               progress: Progress = None) -> Lab:
    """Makes a synthetic lab dataset as ``vahf synthesize GENERATOR --out
    OUT``: the model at stated parameter values plays the lab. Returns it,
    loaded (a Lab)."""
    callback, _ = _progress(progress)
    try:
        _vahf.synthesize(os.fspath(generator), os.fspath(out), _threads(threads),
                         callback)
    finally:
        _close(callback)
    return load_lab(os.path.join(os.fspath(out), "dataset.json"))

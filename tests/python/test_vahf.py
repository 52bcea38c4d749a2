"""Tests of the Python module vahf (docs/python.md), run by ctest as
python.module: the module's trial, run and synthesize give the command's
bits (trace CSV bytes, results digest, every CSV file), verify and replay
confirm a run, its DataFrames hold the CSVs' values bit for bit, each error tier is raised with its fields (a failed
internal check included, the interpreter going on), the GIL is released
while trials run (two Python threads meet at a barrier, each inside a run),
and Ctrl-C stops a run with KeyboardInterrupt.

Environment: VAHF_CLI, the vahf command of the same build; the working
directory is the repository's root; PYTHONPATH holds the build's python/.
"""

import csv
import filecmp
import json
import math
import os
import subprocess
import sys
import threading

import pytest

import vahf

CLI = os.environ.get("VAHF_CLI", "build/release/tools/vahf")
PEG = "experiments/scenes/peg_in_hole.json"
TABLE1 = "experiments/table1.json"
# table1 at 2 cycles per condition: the same code path, a few seconds.
TRIALS = 2


def command(*args):
    return subprocess.run([CLI, *args], capture_output=True, text=True,
                          check=False)


def same_bits(text, value):
    """Whether a CSV cell's number is the DataFrame's value, bit for bit."""
    if isinstance(value, str):
        return text == value
    number = float(text)
    if math.isnan(number):
        return math.isnan(value)
    return number.hex() == float(value).hex()


def assert_frame_is_csv(frame, path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    assert list(frame.columns) == rows[0]
    assert len(frame) == len(rows) - 1
    for i, row in enumerate(rows[1:]):
        for j, text in enumerate(row):
            value = frame.iat[i, j]
            if text == "":
                assert value != value or value == "", (path, i, j)
                continue
            assert same_bits(text, value), (path, i, rows[0][j], text, value)


def test_trial_is_the_command_s(tmp_path):
    trace = tmp_path / "trace.csv"
    done = command("trial", PEG, "--seed", "1", "--trace", str(trace))
    assert done.returncode == 0, done.stderr
    r = vahf.trial(PEG, seed=1)
    assert r.status == "completed"
    # The summary is the command's, but for the measured wall and CPU time.
    measured = "simulated:"
    assert [line for line in r.summary.splitlines()
            if not line.startswith(measured)] == [
        line for line in done.stdout.splitlines()[:-1]
        if not line.startswith(measured)]
    assert r.trace_csv.encode() == trace.read_bytes()
    assert_frame_is_csv(r.trace, trace)
    assert r.counters["decisions"] == r.trace_rows == len(r.trace)


def test_run_is_the_command_s_on_1_and_2_threads(tmp_path):
    cli_out = tmp_path / "cli"
    done = command("run", TABLE1, "--seed", "1", "--trials", str(TRIALS),
                   "--out", str(cli_out))
    assert done.returncode == 0, done.stderr
    with open(cli_out / "manifest.json") as f:
        digest = json.load(f)["results_digest"]
    for threads in (1, 2):
        out = tmp_path / ("py%d" % threads)
        run = vahf.run(TABLE1, seed=1, trials=TRIALS, threads=threads, out=out)
        assert run.digest == digest, threads
        for name in run.manifest["result_files"]:
            assert filecmp.cmp(cli_out / name, out / name, shallow=False), name
    assert run.tables, "a table1 run writes CSV tables"
    for name, frame in run.tables.items():
        assert_frame_is_csv(frame, out / (name + ".csv"))
    assert run.claims and all(
        {"verdict", "test", "evidence"} <= set(c) for c in run.claims)


def test_verify_and_replay_a_run(tmp_path):
    run = vahf.run(TABLE1, trials=TRIALS, threads=2, out=tmp_path / "run")
    assert vahf.verify(run.out)
    assert vahf.replay(run.out, "table1_cycles.csv:2")
    assert "table1" in vahf.check(TABLE1)


def test_synthesize_and_load_lab(tmp_path):
    # The shipped synthetic dataset is vahf synthesize's output, byte for
    # byte (tests/tools/cli_test.sh): so is the module's.
    lab = vahf.synthesize("data/synthetic_block/generator.json",
                          tmp_path / "lab", threads=2)
    assert filecmp.cmp(tmp_path / "lab" / "trials.csv",
                       "data/synthetic_block/trials.csv", shallow=False)
    assert_frame_is_csv(lab.trials, "data/synthetic_block/trials.csv")
    assert lab.name == "synthetic_block" and lab.segments is None
    shipped = vahf.load_lab("data/synthetic_block")
    assert shipped.trials.equals(lab.trials)


def test_params_is_the_table():
    table = vahf.params()
    assert list(table.columns) == [
        "name", "unit", "rule", "default", "description"]
    assert "simulation/accuracy" in set(table["name"])


def test_a_missing_file_is_an_input_error():
    with pytest.raises(vahf.InputError) as e:
        vahf.trial("experiments/scenes/no_such_scene.json", seed=1)
    assert e.value.file == "experiments/scenes/no_such_scene.json"
    assert e.value.rule
    assert str(e.value).startswith(e.value.file)


def test_a_nan_parameter_is_an_input_error():
    with pytest.raises(vahf.InputError) as e:
        vahf.trial(PEG, seed=1, set={"simulation/accuracy": float("nan")})
    assert e.value.file == "set"
    assert e.value.field == "/simulation/accuracy"
    assert e.value.value == "nan"
    assert e.value.rule == "must be a finite number"


def test_an_unknown_key_is_an_input_error(tmp_path):
    with open(PEG) as f:
        scene = json.load(f)
    scene["colour"] = "red"
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(scene))
    with pytest.raises(vahf.InputError) as e:
        vahf.load_scene(path)
    assert e.value.file == str(path)
    assert e.value.field == "/colour"
    assert e.value.rule
    with pytest.raises(vahf.InputError) as e:
        vahf.trial(PEG, seed=1, set={"simulation/colour": 1})
    assert e.value.value == "simulation/colour"


def test_a_failed_computation_is_a_computation_error(tmp_path):
    # A calibration on one cycle per operator: valid input, no usable target.
    with pytest.raises(vahf.ComputationError) as e:
        vahf.run("experiments/calibrate_synthetic.json", trials=1,
                 out=tmp_path / "run")
    assert e.value.reason == "too_few_values"
    assert "too few completed trials" in e.value.rule
    assert e.value.file == e.value.field == e.value.value == ""


def test_threads_out_of_range_is_an_input_error(tmp_path):
    with pytest.raises(vahf.InputError) as e:
        vahf.run(TABLE1, trials=TRIALS, threads=0, out=tmp_path / "run")
    assert (e.value.file, e.value.value) == ("threads", "0")


def test_a_failed_internal_check_is_an_internal_error():
    with pytest.raises(vahf.InternalError) as e:
        vahf._vahf._fail_internal_check()
    assert e.value.file.endswith("_vahf.cc")
    assert e.value.line > 0
    assert e.value.field == "line %d" % e.value.line
    assert "1 + 1 == 3" in e.value.value
    assert e.value.rule
    # The interpreter goes on, and so does the module.
    assert vahf.trial(PEG, seed=1, trace=False).status == "completed"


def test_the_gil_is_released_while_trials_run(tmp_path):
    # Each thread's progress callback is called on that thread while its
    # run's batch of trials is under way (done < total); the first call
    # waits at the barrier. Both pass it only if both runs are under way at
    # once, each calling thread waiting for its trials without the GIL.
    barrier = threading.Barrier(2, timeout=120)
    first = {}

    def progress(label, unit, done, total):
        me = threading.current_thread()
        if me not in first:
            first[me] = (done, total)
            barrier.wait()

    errors = []

    def work(k):
        try:
            vahf.run(TABLE1, trials=TRIALS, out=tmp_path / ("t%d" % k),
                     progress=progress)
        except Exception as error:  # noqa: BLE001 - reported below
            errors.append(error)

    threads = [threading.Thread(target=work, args=(k,)) for k in (0, 1)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors, errors
    assert not barrier.broken
    assert len(first) == 2
    assert all(done < total for done, total in first.values()), first


CTRL_C = r"""
import os, signal, sys, threading
import vahf
sent = []
def progress(label, unit, done, total):
    if not sent:  # once the run is under way: Ctrl-C from another thread
        sent.append(1)
        threading.Timer(0.2, os.kill, (os.getpid(), signal.SIGINT)).start()
try:
    vahf.run("experiments/assembly_time.json", trials=50, out=sys.argv[1],
             progress=progress)
    print("finished")
except KeyboardInterrupt:
    print("interrupted")
print(vahf.trial("experiments/scenes/peg_in_hole.json", seed=1,
                 trace=False).status)
"""


def test_ctrl_c_stops_a_run(tmp_path):
    out = tmp_path / "int"
    done = subprocess.run([sys.executable, "-c", CTRL_C, str(out)],
                          capture_output=True, text=True, timeout=600,
                          check=False)
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == ["interrupted", "completed"], done.stdout
    assert not out.exists()

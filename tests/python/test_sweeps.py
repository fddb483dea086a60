"""agvbench.run (issue 48, stage 2): the report of `agvbench run` for the same config, and the
runs as a DataFrame whose rows are the journal's runs, value for value."""

import json
import math
import os
import signal
import sys

import numpy
import pandas
import pytest

import agvbench

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "reports"))
from agvreports.runs import journal_records  # noqa: E402  (the journal's own Python reader)

CONFIG = {
    "name": "python-sweep",
    "seed": 7,
    "generators": ["uniform", "maze"],
    "sizes": [16, [24, 20]],
    "densities": [0.1, 0.25],
    "maps_per_cell": 4,
    "planners": ["astar", "dijkstra", {"name": "rrt", "label": "rrt"},
                 {"name": "ma_star", "only": {"maps_per_cell": 2}}],
    "baseline": "astar",
}


@pytest.fixture(scope="module")
def swept(tmp_path_factory, cli):
    tmp = tmp_path_factory.mktemp("sweep")
    config = tmp / "config.json"
    config.write_text(json.dumps(CONFIG))
    cli("run", config, "--out", tmp / "cli.json", "--runs-out", tmp / "cli.jsonl", "--quiet")
    calls = []
    got = agvbench.run(CONFIG, threads=2, out=tmp / "py.json", runs_out=tmp / "py.jsonl",
                       progress=lambda done, total: calls.append((done, total)))
    return tmp, got, calls


def test_report_is_the_command_lines(swept, cli):
    tmp, got, _ = swept
    assert got.complete
    digest = {name: cli("digest", tmp / name).split()[0] for name in ("cli.json", "py.json")}
    assert digest["cli.json"] == digest["py.json"]
    with open(tmp / "py.json") as f:
        assert got.report == json.load(f)


def test_runs_are_the_journals_runs(swept):
    tmp, got, _ = swept
    frame = got.runs
    records = [r for _, r in journal_records(tmp / "py.jsonl")]
    assert len(frame) == len(records) == got.report["coverage"]["runs_present"]
    by_key = {(r["cell"], r["map_index"], r["planner"]): r for r in records}
    for row in frame.itertuples(index=False):
        r = by_key[(row.cell, row.map_index, row.planner)]
        assert row.outcome == r["outcome"]
        assert row.plan_time_ns == r["timing"]["plan_time_ns"]
        for name, value in r["metrics"].items():
            mine = getattr(row, name)
            if value is None:
                assert math.isnan(mine), name
            else:
                assert mine == value, (name, mine, value)


def test_frame_columns_and_order(swept):
    _, got, _ = swept
    frame = got.runs
    for column in ("cell", "generator", "width", "height", "density", "map_index", "seed",
                   "planner", "outcome", "path_length", "collision_checks", "plan_time_ns"):
        assert column in frame.columns, column
    assert set(frame["planner"]) == {"astar", "dijkstra", "rrt", "ma_star"}
    assert (frame["seed"] == 7).all()
    assert (frame.loc[frame["planner"] == "ma_star", "map_index"] < 2).all()
    maze = frame[frame["generator"] == "maze"]
    assert set(zip(maze["width"], maze["height"])) == {(16, 16), (24, 20)}
    keys = list(zip(frame["cell"].cat.codes, frame["map_index"], frame["planner"].cat.codes))
    assert keys == sorted(keys)  # (cell, map index, planner) order, on any thread count


def test_progress_is_called_on_the_calling_thread(swept):
    _, got, calls = swept
    total = got.report["coverage"]["runs_expected"]
    assert calls and calls[-1] == (total, total)
    assert all(a[0] <= b[0] for a, b in zip(calls, calls[1:]))


def test_thread_counts_and_config_files_agree(tmp_path):
    one = agvbench.run(CONFIG, threads=1)
    path = tmp_path / "c.json"
    path.write_text(json.dumps(CONFIG))
    two = agvbench.run(path, threads=2)
    timing = ("plan_time_ns",)
    pandas.testing.assert_frame_equal(one.runs.drop(columns=list(timing)),
                                      two.runs.drop(columns=list(timing)))
    assert one.runs is not None and agvbench.run(CONFIG, keep_runs=False).runs is None


def test_shards_cover_the_sweep():
    whole = agvbench.run(CONFIG, threads=2).runs
    parts = [agvbench.run(CONFIG, threads=2, shard=(i, 3)).runs for i in range(3)]
    joined = pandas.concat(parts).sort_values(["cell", "map_index", "planner"])
    assert len(joined) == len(whole)
    assert sorted(joined["path_length"].fillna(-1)) == sorted(whole["path_length"].fillna(-1))


@pytest.mark.parametrize("kwargs,field", [
    (dict(config={**CONFIG, "maps_per_cell": 0}), "maps_per_cell"),
    (dict(config={**CONFIG, "bogus": 1}), "bogus"),
    (dict(config=CONFIG, threads=-1), "threads"),
    (dict(config=CONFIG, shard=(3, 3)), "shard[0]"),
    (dict(config=CONFIG, shard=(0,)), "shard"),
    (dict(config="/no/such/config.json"), "config file"),
])
def test_bad_input_raises_value_error_naming_the_field(kwargs, field):
    with pytest.raises(ValueError) as raised:
        agvbench.run(**kwargs)
    assert field in str(raised.value), str(raised.value)


def test_outputs_never_overwrite_inputs_or_journals(tmp_path):
    journal = tmp_path / "runs.jsonl"
    first = agvbench.run(CONFIG, runs_out=journal)
    before = journal.read_bytes()
    # The same call again resumes the journal: every run is restored, none is written twice.
    again = agvbench.run(CONFIG, runs_out=journal)
    assert journal.read_bytes() == before
    assert again.report["coverage"] == first.report["coverage"]
    with pytest.raises(ValueError, match="journal"):
        agvbench.run({**CONFIG, "seed": 8}, runs_out=journal)  # another sweep's journal
    assert journal.read_bytes() == before
    config = tmp_path / "c.json"
    config.write_text(json.dumps(CONFIG))
    with pytest.raises(ValueError, match="out"):
        agvbench.run(config, out=config)
    assert json.loads(config.read_text()) == CONFIG


LONG = {**CONFIG, "generators": ["uniform"], "sizes": [48], "densities": [0.2],
        "maps_per_cell": 400, "planners": ["astar", "rrt"]}


def test_ctrl_c_then_the_same_call_resumes(tmp_path, cli):
    journal = tmp_path / "runs.jsonl"

    def ctrl_c(done, total):
        if done > 0:
            signal.raise_signal(signal.SIGINT)

    with pytest.raises(KeyboardInterrupt):
        agvbench.run(LONG, threads=2, runs_out=journal, progress=ctrl_c)
    recorded = len(list(journal_records(journal)))
    assert 0 < recorded < 800
    resumed = agvbench.run(LONG, threads=2, runs_out=journal, out=tmp_path / "resumed.json")
    whole = agvbench.run(LONG, threads=1, out=tmp_path / "whole.json")
    assert resumed.complete
    assert cli("digest", tmp_path / "resumed.json").split()[0] == \
        cli("digest", tmp_path / "whole.json").split()[0]
    pandas.testing.assert_frame_equal(resumed.runs.drop(columns=["plan_time_ns"]),
                                      whole.runs.drop(columns=["plan_time_ns"]))


def without(frame, *columns):
    return frame.drop(columns=list(columns)).reset_index(drop=True)


def test_read_runs_gives_the_sweeps_frame_back(swept):
    tmp, got, _ = swept
    mine = agvbench.read_runs(tmp / "py.jsonl")
    assert mine["seed"].isna().all()  # a journal does not repeat the seed
    pandas.testing.assert_frame_equal(without(mine, "seed"), without(got.runs, "seed"))
    theirs = agvbench.read_runs(tmp / "cli.jsonl")  # the command line's journal
    pandas.testing.assert_frame_equal(without(theirs, "seed", "plan_time_ns"),
                                      without(got.runs, "seed", "plan_time_ns"))


def test_read_runs_reads_gzip_and_leaves_a_torn_tail_out(tmp_path):
    gz = tmp_path / "runs.jsonl.gz"
    got = agvbench.run(CONFIG, runs_out=gz)
    pandas.testing.assert_frame_equal(without(agvbench.read_runs(gz), "seed"),
                                      without(got.runs, "seed"))
    plain = tmp_path / "runs.jsonl"
    agvbench.run(CONFIG, runs_out=plain, keep_runs=False)
    lines = plain.read_bytes().splitlines(keepends=True)
    plain.write_bytes(b"".join(lines[:-1]) + lines[-1][:-5])  # a kill's half-written last line
    assert len(agvbench.read_runs(plain)) == len(got.runs) - 1
    with pytest.raises(ValueError, match="no_such.jsonl"):
        agvbench.read_runs(tmp_path / "no_such.jsonl")


def test_read_runs_reads_a_results_database(tmp_path, cli):
    config = tmp_path / "c.json"
    config.write_text(json.dumps(CONFIG))
    db = tmp_path / "results.db"
    cli("run", config, "--out", tmp_path / "r.json", "--runs-out", tmp_path / "r.jsonl", "--db", db,
        "--quiet")
    from_db = agvbench.read_runs(db)
    from_journal = agvbench.read_runs(tmp_path / "r.jsonl")
    assert (from_db["seed"] == 7).all()
    pandas.testing.assert_frame_equal(without(from_db, "seed"), without(from_journal, "seed"))
    cli("run", config, "--out", tmp_path / "r2.json", "--db", db, "--quiet")
    with pytest.raises(ValueError, match="experiment: .* holds 2 experiments"):
        agvbench.read_runs(db)
    pandas.testing.assert_frame_equal(without(agvbench.read_runs(db, experiment=2), "plan_time_ns"),
                                      without(from_db, "plan_time_ns"))


def test_shards_merge_into_the_whole_report(tmp_path, cli):
    journals = [tmp_path / f"shard{i}.jsonl" for i in range(3)]
    for i, journal in enumerate(journals):
        agvbench.run(CONFIG, threads=2, shard=(i, 3), runs_out=journal, keep_runs=False)
    merged = agvbench.merge(CONFIG, journals, out=tmp_path / "merged.json")
    whole = agvbench.run(CONFIG, threads=2, out=tmp_path / "whole.json")
    assert merged.complete
    assert cli("digest", tmp_path / "merged.json").split()[0] == \
        cli("digest", tmp_path / "whole.json").split()[0]
    pandas.testing.assert_frame_equal(without(merged.runs, "plan_time_ns"),
                                      without(whole.runs, "plan_time_ns"))
    partial = agvbench.merge(CONFIG, journals[:2])
    assert not partial.complete and len(partial.runs) < len(whole.runs)
    with pytest.raises(ValueError, match="out"):
        agvbench.merge(CONFIG, journals, out=journals[0])


def test_map_file_cells_in_the_frame_and_read_back(tmp_path):
    (tmp_path / "room.map").write_text("type octile\nheight 6\nwidth 8\nmap\n" + "\n".join(
        ["........", "...@@...", "........", "..@.....", "..@.....", "........"]) + "\n")
    config = {**CONFIG, "generators": ["uniform", {"name": "movingai",
                                                   "params": {"files": [str(tmp_path / "room.map")]}}],
              "maps_per_cell": 3}
    got = agvbench.run(config, runs_out=tmp_path / "runs.jsonl")
    files = got.runs[got.runs["generator"] == "movingai"]
    assert len(files) == 3 * 3 + 2  # ma_star runs on the first 2 maps of each cell
    assert set(zip(files["width"], files["height"])) == {(8, 6)}
    back = agvbench.read_runs(tmp_path / "runs.jsonl")
    mine = back[back["cell"] == "movingai/room.map"]
    assert len(mine) == 11 and mine["generator"].isna().all() and mine["width"].isna().all()
    assert mine["path_length"].tolist() == files["path_length"].tolist()
    generated = back[back["cell"] != "movingai/room.map"]
    assert (generated["generator"] == "uniform").all() and generated["width"].notna().all()

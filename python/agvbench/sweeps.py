"""Whole sweeps: the report `agvbench run` writes, and the runs as a pandas DataFrame."""

import os
import sqlite3
from dataclasses import dataclass
from typing import Optional

import numpy
import pandas

from agvbench import _core
from agvbench.plain import plain


@dataclass(frozen=True)
class SweepResult:
    """report: the JSON report as a dict (what `agvbench run` writes for the config);
    runs: a DataFrame, one row per run (None with keep_runs=False); complete: every scheduled
    run is present."""

    report: dict
    runs: Optional[pandas.DataFrame]
    complete: bool


def run(config, *, threads=None, out=None, runs_out=None, progress=None, shard=None,
        keep_runs=True):
    """Runs the sweep of `config` (a dict, or the path of a config file) as `agvbench run` does.

    threads: worker threads (default the config's; 0 = all); out: also write the report there;
    runs_out: the journal (JSON Lines of per-run records); progress: called as progress(done,
    total) on this thread about ten times a second and at the end; shard: (i, n), only the
    i-th of n slices, split by map; keep_runs=False builds no DataFrame (for sweeps too large to
    hold). The engine's threads run with the GIL released; Ctrl-C raises KeyboardInterrupt once
    the runs in flight are over and the journal is flushed.
    """
    path = os.fspath(config) if isinstance(config, (str, os.PathLike)) else ""
    got = _core.run(None if path else plain(config), path, plain(threads),
                    "" if out is None else os.fspath(out),
                    "" if runs_out is None else os.fspath(runs_out), plain(shard),
                    bool(keep_runs), progress)
    runs = runs_frame(got["runs"]) if keep_runs else None
    return SweepResult(report=got["report"], runs=runs, complete=got["complete"])


def merge(config, journals, *, out=None, keep_runs=True):
    """One report (and DataFrame) from the journals of a sharded or interrupted sweep of
    `config`, as `agvbench merge CONFIG JOURNAL...`: a SweepResult whose .complete says whether
    every scheduled run was found. out: also write the report there."""
    path = os.fspath(config) if isinstance(config, (str, os.PathLike)) else ""
    if isinstance(journals, (str, os.PathLike)):
        journals = [journals]
    got = _core.merge(None if path else plain(config), path, [os.fspath(j) for j in journals],
                      "" if out is None else os.fspath(out), bool(keep_runs))
    runs = runs_frame(got["runs"]) if keep_runs else None
    return SweepResult(report=got["report"], runs=runs, complete=got["complete"])


def runs_frame(runs):
    """The DataFrame of the engine's run columns: cell, generator, width, height, density,
    map_index, seed, planner, outcome, one column per metric, plan_time_ns."""
    c = runs["columns"]
    cells = runs["cells"]
    cell = c["cell"]

    def per_cell(key, dtype, missing):
        # A journal's map-file cell has no generator, size or density: `missing` there.
        values = [x[key] for x in cells]
        if any(v is None for v in values):
            return pandas.array(values, dtype=missing)[cell]
        return numpy.asarray(values, dtype=dtype)[cell]

    generators = [x["generator"] for x in cells]
    names = sorted({g for g in generators if g is not None})
    generator_code = numpy.asarray([-1 if g is None else names.index(g) for g in generators],
                                   dtype=numpy.int16)
    density = per_cell("density", numpy.float64, "Float64")
    frame = {
        "cell": pandas.Categorical.from_codes(cell, [x["key"] for x in cells]),
        "generator": pandas.Categorical.from_codes(generator_code[cell], names),
        "width": per_cell("width", numpy.int32, "Int32"),
        "height": per_cell("height", numpy.int32, "Int32"),
        "density": density if isinstance(density, numpy.ndarray)
        else density.to_numpy(dtype=numpy.float64, na_value=numpy.nan),
        "map_index": c["map_index"],
        "seed": numpy.full(len(cell), runs["seed"], dtype=numpy.int64) if runs["seed"] is not None
        else pandas.array([None] * len(cell), dtype="Int64"),
        "planner": pandas.Categorical.from_codes(c["planner"], runs["planners"]),
        "outcome": pandas.Categorical.from_codes(c["outcome"].astype(numpy.int16),
                                                 runs["outcomes"]),
    }
    for name, column in runs["metrics"]:
        frame[name] = column
    frame["plan_time_ns"] = c["plan_time_ns"]
    return pandas.DataFrame(frame)


def read_runs(path, experiment=None):
    """The DataFrame of a sweep's runs read back: from its journal (`--runs-out`, any version the
    engine reads, .jsonl.gz too; a torn last line is left out, a run recorded twice counted once)
    or from a results database (`--db`, SQLite: its only experiment, or experiment=ID).

    The columns of run()'s DataFrame; a journal does not repeat the sweep's seed (<NA>), and a
    map-file cell has no generator, size or density.
    """
    path = os.fspath(path)
    if is_database(path):
        return database_frame(path, experiment)
    if experiment is not None:
        raise ValueError(f"experiment: {path} is a journal (one sweep), not a results database")
    return runs_frame(_core.read_journal(path))


def is_database(path):
    try:
        with open(path, "rb") as f:
            return f.read(16) == b"SQLite format 3\x00"
    except OSError:
        return False  # the journal reader names the file and the error


def database_frame(path, experiment):
    """The runs of one experiment of a results database (engine/outputs/results_db.h: runs,
    cells, planners, and run_metrics with the finite metrics of each run), as runs_frame's."""
    with sqlite3.connect(f"file:{path}?mode=ro", uri=True) as db:
        ids = [r[0] for r in db.execute("SELECT experiment_id FROM experiments ORDER BY 1")]
        if experiment is None and len(ids) != 1:
            raise ValueError(f"experiment: {path} holds {len(ids)} experiments ({ids}); name one")
        experiment = ids[0] if experiment is None else experiment
        if experiment not in ids:
            raise ValueError(f"experiment: {path} has no experiment {experiment} (it has {ids})")
        query = lambda sql: pandas.read_sql_query(sql, db, params=(experiment,))  # noqa: E731
        cells = query("SELECT cell_id, cell AS key, generator, width, height, density FROM cells "
                      "WHERE experiment_id = ? ORDER BY cell_id")
        planners = query("SELECT planner_id, label FROM planners WHERE experiment_id = ? "
                         "ORDER BY planner_id")
        seed = query("SELECT seed FROM experiments WHERE experiment_id = ?")["seed"][0]
        runs = query("SELECT run_id, cell_id, planner_id, map_index, outcome, plan_time_ns "
                     "FROM runs WHERE experiment_id = ? ORDER BY cell_id, map_index, planner_id")
        values = query("SELECT m.run_id, m.metric, m.value FROM run_metrics m JOIN runs r "
                       "ON r.run_id = m.run_id WHERE r.experiment_id = ?")
    outcomes = _core.outcome_names()
    wide = values.pivot(index="run_id", columns="metric", values="value")
    names = _core.metric_names()
    names += sorted(set(wide.columns) - set(names))
    wide = wide.reindex(index=runs["run_id"], columns=names)
    return runs_frame({
        "columns": {
            "cell": position(runs["cell_id"], cells["cell_id"]),
            "map_index": runs["map_index"].to_numpy(numpy.int32),
            "planner": position(runs["planner_id"], planners["planner_id"]),
            "outcome": runs["outcome"].map(outcomes.index).to_numpy(numpy.uint8),
            "plan_time_ns": runs["plan_time_ns"].to_numpy(numpy.int64),
        },
        "metrics": [(n, wide[n].to_numpy(numpy.float64)) for n in names],
        "cells": cells.drop(columns="cell_id").to_dict("records"),
        "planners": list(planners["label"]),
        "outcomes": outcomes,
        "seed": int(seed),
    })


def position(ids, in_order):
    """The position of each of `ids` in the sorted id column `in_order`."""
    return numpy.searchsorted(in_order.to_numpy(), ids.to_numpy()).astype(numpy.int32)

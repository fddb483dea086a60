"""The per-run journal of a sweep (`agvbench run --runs-out RUNS.jsonl`, reports/SCHEMA.md
"Per-run records") for the pictures and the HTML report: read, checked against its report, and
grouped by cell and planner. Standard library only.
"""

import json

from agvreports.cells import cell_key
from agvreports.numeric import finite
from agvreports.report_io import ReportError

JOURNAL_VERSION = 1  # engine/run_record.h kJournalVersion


class Runs:
    """Values per (cell, planner): `values(cell, planner, metric)` is the list over successful
    runs (metrics) or over every run (`plan_time_ns`, failures included, as the report's
    timing), in map-index order."""

    def __init__(self, path):
        self.path = path
        self.by = {}  # cell -> planner -> [(map_index, outcome, metrics, plan_time_ns)]
        self.count = 0

    def values(self, cell, planner, metric):
        rows = sorted(self.by.get(cell, {}).get(planner, []), key=lambda r: r[0])
        if metric == "plan_time_ns":
            return [float(r[3]) for r in rows if finite(r[3])]
        return [float(r[2][metric]) for r in rows
                if r[1] == "success" and finite(r[2].get(metric))]


def _check_version(r, n):
    tool, version = r.get("tool"), r.get("journal_version")
    if tool != "agvbench" or version != JOURNAL_VERSION:
        raise ReportError(f"line {n}: a record of tool {tool!r}, journal_version {version!r}; "
                          f"this script reads tool 'agvbench', journal_version {JOURNAL_VERSION} "
                          "(reports/SCHEMA.md, Per-run records)")


def journal_records(path):
    """Yield (line number, record) for each record of RUNS.jsonl, each checked to be an agvbench
    journal record of this version with the keys every reader needs. Raises ReportError naming
    the line; OSError and UnicodeDecodeError pass through to the caller."""
    with open(path, "r", encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            line = line.strip()
            if not line:
                continue
            try:
                r = json.loads(line)
            except json.JSONDecodeError as e:
                raise ReportError(f"line {n}: not valid JSON: {e.msg}") from None
            if not isinstance(r, dict):
                raise ReportError(f"line {n}: expected a JSON object (an agvbench --runs-out record)")
            # A record that names its tool or version is judged by them first (another version's
            # keys may differ); one that names neither, by its keys.
            if "tool" in r or "journal_version" in r:
                _check_version(r, n)
            for key in ("planner", "cell", "map_index", "outcome", "metrics"):
                if key not in r:
                    raise ReportError(f"line {n}: missing key '{key}' (not an agvbench --runs-out record)")
            _check_version(r, n)
            if not isinstance(r["metrics"], dict):
                raise ReportError(f"line {n}.metrics: expected an object")
            yield n, r


def config_hash(config):
    """The hash a journal's records carry for the report's `config` (agvbench compare's
    report_config_hash): 64-bit FNV-1a over the config as the engine writes it compactly, keys
    sorted, non-ASCII characters as themselves."""
    text = json.dumps(config, sort_keys=True, separators=(",", ":"), ensure_ascii=False)
    h = 0xcbf29ce484222325
    for byte in text.encode("utf-8"):
        h = ((h ^ byte) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
    return f"{h:016x}"


def load_runs(path, doc):
    """Read RUNS.jsonl; every record must be an agvbench journal record of this version of the
    report `doc`'s sweep: its config hash, cell and planner (a journal of another sweep, even of
    a config of the same name, is refused)."""
    want = config_hash(doc["config"]) if isinstance(doc.get("config"), dict) else None
    cells = {cell_key(c) for c in doc["cells"]}
    planners = {p["planner"] for c in doc["cells"] for p in c["planners"]}
    runs = Runs(path)
    try:
        for n, r in journal_records(path):
            if want is not None and r.get("config_hash") != want:
                raise ReportError(f"line {n}: a record of config {r.get('config_hash')!r}, not of "
                                  f"the report's (hash {want!r}): the journal of another sweep")
            if r["cell"] not in cells:
                raise ReportError(f"line {n}: cell {r['cell']!r} is not in the report "
                                  "(the journal of another sweep?)")
            if r["planner"] not in planners:
                raise ReportError(f"line {n}: planner {r['planner']!r} is not in the report "
                                  "(the journal of another sweep?)")
            t = (r.get("timing") or {}).get("plan_time_ns") if isinstance(r.get("timing"), dict) else None
            runs.by.setdefault(r["cell"], {}).setdefault(r["planner"], []).append(
                (r["map_index"], r["outcome"], r["metrics"], t))
            runs.count += 1
    except FileNotFoundError:
        raise ReportError("no such file") from None
    except IsADirectoryError:
        raise ReportError("is a directory, expected a JSON Lines file") from None
    except UnicodeDecodeError as e:
        raise ReportError(f"not UTF-8 text ({e.reason})") from None
    except OSError as e:
        raise ReportError(f"cannot read: {e.strerror}") from None
    if runs.count == 0:
        raise ReportError("no records (an empty journal)")
    return runs

"""The per-run journal of a sweep (`agvbench run --runs-out RUNS.jsonl`, reports/SCHEMA.md
"Per-run records") for the pictures and the HTML report: read, checked against its report, and
grouped by cell and planner. Standard library only.
"""

import json
import zlib

from agvreports.cells import cell_key
from agvreports.numeric import finite
from agvreports.report_io import ReportError

JOURNAL_VERSION = 2  # engine/outputs/run_record.h kJournalVersion
JOURNAL_VERSIONS_READ = (1, 2)  # version 1 journals are still read

# The engine's run metrics, in the order a version 2 header must start its metric list with
# (engine/judge/run_metrics.h kRunMetricNames): the derived ones are rebuilt by position.
RUN_METRICS = ("path_length", "path_length_m", "waypoints", "turns", "turn_angle_rad",
               "max_turn_rad", "smoothness_mean", "smoothness_max", "min_clearance",
               "min_clearance_m", "motion_time_s", "optimality_ratio", "any_angle_ratio",
               "scen_ratio")


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


def _refuse_version(r, n):
    tool, version = r.get("tool"), r.get("journal_version")
    raise ReportError(f"line {n}: a record of tool {tool!r}, journal_version {version!r}; "
                      f"this script reads tool 'agvbench', journal_version {JOURNAL_VERSION} "
                      f"(and 1) (reports/SCHEMA.md, Per-run records)")


def _ratio(length, reference):
    """engine/judge/run_executor.cpp set_ratio: length / reference, 1 for a zero reference."""
    if length is None or reference is None:
        return None
    if reference > 0:
        return length / reference
    return 1.0 if reference == 0 else None


def rebuild_derived(m, explicit, facts, cell_edge):
    """Sets the derived metrics of `m` (name -> float) that `explicit` does not name, exactly as
    engine/outputs/run_record.cpp rebuild_derived_metrics does (the same operations in the same order,
    so the same doubles). Absent where their inputs are."""
    def put(name, v):
        if name not in explicit:
            if v is None:
                m.pop(name, None)
            else:
                m[name] = v
    length, turn = m.get("path_length"), m.get("turn_angle_rad")
    put("path_length_m", length * cell_edge if length is not None else None)
    put("smoothness_mean", turn / length if turn is not None and length is not None and length > 0 else None)
    put("min_clearance_m", m["min_clearance"] * cell_edge if m.get("min_clearance") is not None else None)
    put("optimality_ratio", _ratio(length, facts.get("optimal_length")))
    put("any_angle_ratio", _ratio(length, facts.get("any_angle_length")))
    put("scen_ratio", _ratio(length, facts.get("scen_optimum")))


def _need(r, key, n, kind=None):
    if key not in r or (kind is not None and not isinstance(r[key], kind)):
        raise ReportError(f"line {n}: missing or malformed key '{key}' (not an agvbench --runs-out record)")
    return r[key]


class _Segment:
    """A version 2 header and the map facts read after it."""

    def __init__(self, h, n):
        try:
            self.config_hash = h["config_hash"]
            self.sweep_id = h.get("sweep_id") or None  # absent before sweep ids
            self.cells = [(c["cell"], float(c["cell_edge"])) for c in h["cells"]]
            self.planners = [p["label"] for p in h["planners"]]
            self.names = [p.get("name", p["label"]) for p in h["planners"]]
            self.metrics = list(h["metrics"])
        except (KeyError, TypeError, ValueError):
            raise ReportError(f"line {n}: a malformed journal header") from None
        if tuple(self.metrics[:len(RUN_METRICS)]) != RUN_METRICS:
            raise ReportError(f"line {n}: the header's metric order is not this script's "
                              "(written by an agvbench that measures other metrics)")
        self.maps = {}

    def index(self, r, key, table, n):
        v = r.get(key)
        if not isinstance(v, int) or isinstance(v, bool) or not 0 <= v < len(table):
            raise ReportError(f"line {n}: '{key}' {v!r} is not an index of the header's table")
        return v

    def run(self, r, n):
        cell = self.index(r, "cell", self.cells, n)
        key, edge = self.cells[cell]
        mi = _need(r, "map_index", n, int)
        m, explicit = {}, set()
        mask = r.get("mask", 0)
        values = r.get("metrics", [])
        if not isinstance(mask, int) or not isinstance(values, list):
            raise ReportError(f"line {n}: malformed 'mask' or 'metrics'")
        bits = [b for b in range(64) if mask >> b & 1]
        if len(bits) != len(values) or (bits and bits[-1] >= len(self.metrics)):
            raise ReportError(f"line {n}: 'metrics' does not match its 'mask'")
        for b, v in zip(bits, values):
            m[self.metrics[b]] = float(v)
            explicit.add(self.metrics[b])
        for name, v in (r.get("extra") or {}).items():
            explicit.add(name)
            m[name] = None if v is None else float(v)  # null: reported, undefined
        rebuild_derived(m, explicit, self.maps.get((cell, mi), {}), edge)
        p = self.index(r, "planner", self.planners, n)
        return {"planner": self.planners[p], "planner_name": self.names[p], "cell": key,
                "map_index": mi, "outcome": _need(r, "outcome", n, str), "metrics": m,
                "timing": {"plan_time_ns": r.get("plan_time_ns"), "phases": r.get("phases", {})},
                "config_hash": self.config_hash,
                **({"message": r["message"]} if "message" in r else {})}


def _gzip_members(f):
    """The text of each whole member of a gzip journal (one per engine write: whole lines,
    engine/outputs/gzip_members.h), in order; a member cut short at the end (a kill's) is left out."""
    member, d = [], zlib.decompressobj(wbits=31)
    while chunk := f.read(1 << 16):
        while chunk:
            try:
                member.append(d.decompress(chunk))
            except zlib.error as e:
                raise ReportError(f"damaged gzip data: {e}") from None
            if not d.eof:
                break
            yield b"".join(member).decode("utf-8")
            member, chunk, d = [], d.unused_data, zlib.decompressobj(wbits=31)


def _journal_lines(path):
    """(number, line) of each whole line of a journal, plain or gzip; a torn tail is left out."""
    with open(path, "rb") as f:
        gzip = f.read(2) == b"\x1f\x8b"
        f.seek(0)
        if gzip:
            lines = (line for text in _gzip_members(f) for line in text.splitlines(keepends=True))
        else:
            lines = (raw.decode("utf-8") for raw in f)
        for n, raw in enumerate(lines, 1):
            if not raw.endswith("\n"):
                return  # torn last line
            yield n, raw


def journal_records(path, sweep_ids=None):
    """Yield (line number, run record) for each run of RUNS.jsonl, version 1 or 2, each in one
    shape: planner (label), cell (key), map_index, outcome, metrics (name -> value, derived
    ones rebuilt; a version 1 record's nulls kept), timing {plan_time_ns, phases}, config_hash,
    message. RUNS.jsonl.gz (gzip, `--runs-out RUNS.jsonl.gz`) is read as well. Raises ReportError
    naming the line; OSError and UnicodeDecodeError pass through to the caller. A torn tail (a
    last line without its newline, a gzip member cut short: a kill's) is skipped, as the engine
    does. Each segment's sweep id, where its header names one, is added to the set `sweep_ids`."""
    segment = None
    for n, raw in _journal_lines(path):
        line = raw.strip()
        if not line:
            continue
        try:
            r = json.loads(line)
        except json.JSONDecodeError as e:
            raise ReportError(f"line {n}: not valid JSON: {e.msg}") from None
        if not isinstance(r, dict):
            raise ReportError(f"line {n}: expected a JSON object (an agvbench --runs-out record)")
        if "tool" in r or "journal_version" in r:
            if r.get("tool") != "agvbench" or r.get("journal_version") not in JOURNAL_VERSIONS_READ:
                _refuse_version(r, n)
            if r["journal_version"] == JOURNAL_VERSION:
                if r.get("record") != "header":
                    raise ReportError(f"line {n}: a version 2 record naming its version must be its header")
                segment = _Segment(r, n)
                if sweep_ids is not None and segment.sweep_id:
                    sweep_ids.add(segment.sweep_id)
                continue
            # A version 1 record: self-contained.
            for key in ("planner", "cell", "map_index", "outcome", "metrics"):
                _need(r, key, n)
            if not isinstance(r["metrics"], dict):
                raise ReportError(f"line {n}.metrics: expected an object")
            yield n, r
            continue
        if segment is None:
            _refuse_version(r, n)
        if r.get("record") == "map":
            cell = segment.index(r, "cell", segment.cells, n)
            facts = segment.maps.setdefault((cell, _need(r, "map_index", n, int)), {})
            for k in ("optimal_length", "any_angle_length", "scen_optimum", "obstacle_fraction", "rejections"):
                if k in r:
                    facts[k] = r[k]
            continue
        if "record" in r:
            raise ReportError(f"line {n}: unknown record kind {r['record']!r}")
        yield n, segment.run(r, n)


def config_hash(config):
    """The hash a journal's records carry for the report's `config` (agvbench compare's
    report_config_hash): 64-bit FNV-1a over the config as the engine writes it compactly, keys
    sorted, non-ASCII characters as themselves, "sources" (commentary) left out."""
    config = {k: v for k, v in config.items() if k != "sources"}
    text = json.dumps(config, sort_keys=True, separators=(",", ":"), ensure_ascii=False)
    h = 0xcbf29ce484222325
    for byte in text.encode("utf-8"):
        h = ((h ^ byte) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
    return f"{h:016x}"


def check_sweeps(doc, sweep_ids):
    """The journal's sweeps (the ids its segments name) must be exactly the report's
    (environment.sweep_ids; engine/outputs/sweep_identity.h): another sweep of the same config
    has the same config hash but other times. A report from before the ids is not checked."""
    env = doc.get("environment")
    want = env.get("sweep_ids") if isinstance(env, dict) else None
    if not isinstance(want, list) or not want:
        return
    if set(sweep_ids) != set(want):
        have = ", ".join(sorted(sweep_ids)) or "(none: written before sweep ids)"
        raise ReportError(f"holds sweep {have}, but the report is of sweep {', '.join(sorted(want))}: "
                          "not this report's journal (another sweep of the same config has other "
                          "times; a merged report needs every shard's journal, concatenated)")


def matched_records(path, doc):
    """Yield (line number, run record) of RUNS.jsonl, every record checked to be of the report
    `doc`'s sweep: its config hash, cell and planner, and at the end the journal's sweep ids
    (a journal of another sweep, even of the same config, is refused). Raises ReportError."""
    want = config_hash(doc["config"]) if isinstance(doc.get("config"), dict) else None
    cells = {cell_key(c) for c in doc["cells"]}
    planners = {p["planner"] for c in doc["cells"] for p in c["planners"]}
    sweep_ids = set()
    try:
        for n, r in journal_records(path, sweep_ids):
            if want is not None and r.get("config_hash") != want:
                raise ReportError(f"line {n}: a record of config {r.get('config_hash')!r}, not of "
                                  f"the report's (hash {want!r}): the journal of another sweep")
            if r["cell"] not in cells:
                raise ReportError(f"line {n}: cell {r['cell']!r} is not in the report "
                                  "(the journal of another sweep?)")
            if r["planner"] not in planners:
                raise ReportError(f"line {n}: planner {r['planner']!r} is not in the report "
                                  "(the journal of another sweep?)")
            yield n, r
    except FileNotFoundError:
        raise ReportError("no such file") from None
    except IsADirectoryError:
        raise ReportError("is a directory, expected a JSON Lines file") from None
    except UnicodeDecodeError as e:
        raise ReportError(f"not UTF-8 text ({e.reason})") from None
    except OSError as e:
        raise ReportError(f"cannot read: {e.strerror}") from None
    check_sweeps(doc, sweep_ids)


def load_runs(path, doc):
    """Read RUNS.jsonl, the journal of the report `doc`'s sweep (matched_records)."""
    runs = Runs(path)
    for _, r in matched_records(path, doc):
        t = (r.get("timing") or {}).get("plan_time_ns") if isinstance(r.get("timing"), dict) else None
        runs.by.setdefault(r["cell"], {}).setdefault(r["planner"], []).append(
            (r["map_index"], r["outcome"], r["metrics"], t))
        runs.count += 1
    if runs.count == 0:
        raise ReportError("no records (an empty journal)")
    return runs

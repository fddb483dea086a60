"""An `agvbench run` report grouped for the pictures, summary.md and the HTML page: worlds
(generator, size) -> density -> cell, the planners and metrics chosen with --planners /
--metrics, and every planner's style. A map file of a map source (`movingai`, `image`) is a
world of its own, named by its cell (`movingai/arena2.map`), whose one density is its obstacle
share: files of one size are different maps, not points of one curve over density.
Standard library only (the style's colours are plain strings; matplotlib is imported where a
picture is drawn).
"""

import re

from agvreports.cells import cell_key, comparison_of, paired_of, planner_of, summary_of
from agvreports.metrics import METRIC_LABELS, PAIRED_ORDER, TIME
from agvreports.numeric import finite
from agvreports.report_io import ReportError, baseline_label, planner_order
from agvreports.style import Style


def safe_name(text):
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", text).strip("_") or "x"


def density_text(d):
    return f"{d:g}"


def split_list(values):
    """--planners a,b --planners c -> [a, b, c] (order kept, duplicates dropped)."""
    out = []
    for v in values or []:
        for part in v.split(","):
            part = part.strip()
            if part and part not in out:
                out.append(part)
    return out


class Report:
    """The report regrouped for plotting: worlds (gen, w, h) -> {density: cell}."""

    def __init__(self, doc, planners=None, metrics=None):
        self.doc = doc
        self.config = doc.get("config", {})
        self.all_labels = planner_order(doc)
        self.baseline = baseline_label(doc)
        # Colours follow the config's order, so a planner keeps its look under --planners.
        self.style = Style(self.all_labels, self.baseline)
        present = {p["planner"] for c in doc["cells"] for p in c["planners"]}
        if planners:
            for p in planners:
                if p not in present:
                    raise ReportError(f"--planners: no planner '{p}' in the report (it has: "
                                      f"{', '.join(l for l in self.all_labels if l in present)})")
            self.labels = [l for l in self.all_labels if l in planners]
        else:
            self.labels = [l for l in self.all_labels if l in present]
        self.worlds = {}  # (gen, w, h) -> {density: cell}; gen = the cell's name for a map file
        gens = self.config.get("generators")
        sources = {g.get("name") for g in gens if isinstance(g, dict) and "map_files" in g} \
            if isinstance(gens, list) else set()
        for cell in doc["cells"]:
            world = self.cell_key(cell) if cell["generator"] in sources else cell["generator"]
            key = (world, int(cell["width"]), int(cell["height"]))
            self.worlds.setdefault(key, {})[float(cell["density"])] = cell
        self.generators = []
        self.sizes = []
        self.densities = sorted({d for cells in self.worlds.values() for d in cells})
        for (g, w, h) in self.worlds:
            if g not in self.generators:
                self.generators.append(g)
            if (w, h) not in self.sizes:
                self.sizes.append((w, h))
        self.sizes.sort(key=lambda s: (s[0] * s[1], s))
        m = self.config.get("map") if isinstance(self.config.get("map"), dict) else {}
        edge = m.get("cell_edge", 1.0)
        self.cell_edge = edge if finite(edge) else 1.0
        known = self._all_metric_names()
        if metrics:
            for name in metrics:
                if name not in known:
                    raise ReportError(f"--metrics: no metric '{name}' in the report (it has: "
                                      f"{', '.join(known)})")
        self.metric_filter = list(metrics) if metrics else None

    def ordered_worlds(self):
        return sorted(self.worlds, key=lambda k: (self.generators.index(k[0]), k[1] * k[2]))

    @staticmethod
    def world_title(key):
        g, w, h = key
        return f"{g} {w}\u00d7{h}"

    @staticmethod
    def world_file(key):
        g, w, h = key
        return f"{safe_name(g)}_{w}x{h}"

    # The lookups in one cell, as methods for the drawing code's convenience.
    cell_key = staticmethod(cell_key)
    planner = staticmethod(planner_of)
    paired = staticmethod(paired_of)
    summary_of = staticmethod(summary_of)
    comparison_of = staticmethod(comparison_of)

    def present(self, cells):
        """The chosen planners that ran in any of these cells."""
        return [l for l in self.labels if any(self.planner(c, l) for c in cells)]

    def paired_planners(self, cells):
        """The chosen planners, the baseline aside, paired in any cell of {density: cell}."""
        return [l for l in self.labels if l != self.baseline
                and any(self.paired(c, l) for c in cells.values())]

    def world_grid(self):
        """(generator index, size index) of every world the sweep has, in grid order."""
        return [(gi, si) for gi, g in enumerate(self.generators)
                for si, (w, h) in enumerate(self.sizes) if self.worlds.get((g, w, h))]

    def wanted(self, name):
        return self.metric_filter is None or name in self.metric_filter

    def _all_metric_names(self):
        seen = []
        for cell in self.doc["cells"]:
            for p in cell["planners"]:
                for name in p["metrics"]:
                    if name not in seen:
                        seen.append(name)
            for c in cell["paired"]:
                for name in c["metrics"]:
                    if name not in seen:
                        seen.append(name)
        known = [m for m in METRIC_LABELS if m in seen]
        return known + sorted(m for m in seen if m not in METRIC_LABELS) + [TIME]

    def metric_names(self):
        """Metrics with a finite mean somewhere, in panel order (metres dropped when they equal
        cells), filtered by --metrics. Planning time is not among them (it is timing)."""
        seen = []
        for cells in self.worlds.values():
            for cell in cells.values():
                for p in cell["planners"]:
                    for name, s in p["metrics"].items():
                        if name not in seen and finite(s.get("mean")):
                            seen.append(name)
        known = [m for m in METRIC_LABELS if m in seen]
        if abs(self.cell_edge - 1.0) < 1e-12 and self.metric_filter is None:
            known = [m for m in known if m not in ("path_length_m", "min_clearance_m")]
        extras = sorted(m for m in seen if m not in METRIC_LABELS)
        return [m for m in known + extras if self.wanted(m)]

    def paired_names(self):
        seen = []
        for cells in self.worlds.values():
            for cell in cells.values():
                for c in cell["paired"]:
                    for name, comp in c["metrics"].items():
                        if name not in seen and finite(comp.get("geo_mean_ratio")):
                            seen.append(name)
        names = [m for m in PAIRED_ORDER if m in seen] + sorted(m for m in seen if m not in PAIRED_ORDER)
        if self.has_paired_time():
            names.append(TIME)
        return [m for m in names if self.wanted(m)]

    def has_paired_time(self):
        for cells in self.worlds.values():
            for cell in cells.values():
                for c in cell["paired"]:
                    t = (c.get("timing") or {}).get(TIME)
                    if isinstance(t, dict) and finite(t.get("geo_mean_ratio")):
                        return True
        return False

    def metrics_with_time(self):
        """metric_names(), then planning time when the report has it and it is chosen."""
        return self.metric_names() + ([TIME] if self.has_time() and self.wanted(TIME) else [])

    def has_time(self):
        return any(isinstance((p.get("timing") or {}).get(TIME), dict)
                   for cells in self.worlds.values() for c in cells.values() for p in c["planners"])


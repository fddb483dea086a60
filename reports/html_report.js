// The page of reports/html_report.py: controls and charts over the report data embedded in
// <script id="report-data">. Plotly is embedded before this script; nothing is fetched.
(function () {
  "use strict";
  const D = JSON.parse(document.getElementById("report-data").textContent);
  const SYMBOL = {o: "circle", s: "square", "^": "triangle-up", D: "diamond", v: "triangle-down",
    P: "cross", X: "x", "*": "star", "<": "triangle-left", ">": "triangle-right", h: "hexagon",
    p: "pentagon", d: "diamond-tall", H: "hexagon2", "8": "octagon"};
  // Keyed by labels, which are any text: "__proto__" or "constructor" must be a key like another.
  const PLANNER = Object.create(null);
  D.planners.forEach(function (p) { PLANNER[p.label] = p; });
  const CONFIG = {displaylogo: false, responsive: true};
  const state = {world: 0, density: "all", metric: D.metrics[0],
                 planners: D.planners.map(function (p) { return p.label; })};

  // A cell's entry of a planner (its own property only, whatever the label).
  function own(obj, key) {
    return obj && Object.prototype.hasOwnProperty.call(obj, key) ? obj[key] : undefined;
  }
  // Text for plotly (trace names, titles, hover templates): plotly reads <b>, <br>, entities,
  // %{...} templates and $...$ TeX in it; a label is shown as written, its line breaks as <br>.
  function plotlyText(s) {
    return String(s).replace(/&/g, "&amp;").replace(/</g, "&lt;").replace(/>/g, "&gt;")
      .replace(/\$/g, "&#36;").replace(/%/g, "&#37;").replace(/\r\n|\r|\n/g, "<br>");
  }
  function el(tag, attrs, text) {
    const e = document.createElement(tag);
    Object.keys(attrs || {}).forEach(function (k) { e.setAttribute(k, attrs[k]); });
    if (text !== undefined) e.textContent = text;
    return e;
  }
  function symbol(label) {
    const p = PLANNER[label];
    return (SYMBOL[p.marker] || "circle") + (p.open ? "-open" : "");
  }
  function fmt(v) {
    if (v === null || v === undefined || !isFinite(v)) return "\u2013";
    const a = Math.abs(v);
    if (a === 0) return "0";
    if (a >= 1e6 || a < 1e-3) return v.toPrecision(3);
    if (a >= 1000) return v.toFixed(0);
    if (a >= 100) return v.toFixed(1);
    if (a >= 10) return v.toFixed(2);
    return v.toFixed(3);
  }
  function fmtP(p) {
    if (p === null || p === undefined) return "p \u2013";
    return p < 0.001 ? "p<0.001" : "p=" + p.toPrecision(2);
  }
  function dtext(d) { return String(d); }
  function metricTitle(m) {
    const l = D.metric_labels[m];
    return l[1] + (l[0] && l[0] !== l[1] ? " (" + l[0] + ")" : "");
  }
  function world() { return D.worlds[state.world]; }
  function cells() {
    return world().cells.filter(function (c) {
      return state.density === "all" || dtext(c.density) === state.density;
    });
  }
  function chosen() {
    return D.planners.map(function (p) { return p.label; })
      .filter(function (l) { return state.planners.indexOf(l) >= 0; });
  }

  // --- the URL hash keeps the choice (a link reopens the same view) ----------------------------
  function readHash() {
    const h = new URLSearchParams(location.hash.replace(/^#/, ""));
    if (h.has("world")) {
      const i = D.worlds.findIndex(function (w) { return w.title === h.get("world"); });
      if (i >= 0) state.world = i;
    }
    if (h.has("density")) state.density = h.get("density");
    if (h.has("metric") && D.metrics.indexOf(h.get("metric")) >= 0) state.metric = h.get("metric");
    if (h.has("planners")) {
      const want = h.get("planners").split(",").map(decodeLabel);
      state.planners = D.planners.map(function (p) { return p.label; })
        .filter(function (l) { return want.indexOf(l) >= 0; });
    }
  }
  function decodeLabel(s) {
    try { return decodeURIComponent(s); } catch (e) { return s; }  // a hand-written "%"
  }
  function writeHash() {
    const h = new URLSearchParams();
    h.set("world", world().title);
    h.set("density", state.density);
    h.set("metric", state.metric);
    if (state.planners.length !== D.planners.length) {  // each label encoded: its commas stay its own
      h.set("planners", state.planners.map(encodeURIComponent).join(","));
    }
    history.replaceState(null, "", "#" + h.toString());
  }

  // --- controls ------------------------------------------------------------------------------
  function select(id, label, options, value, onChange) {
    const wrap = el("label", {class: "field"}, label);
    const s = el("select", {id: id});
    options.forEach(function (o) {
      const opt = el("option", {value: o[0]}, o[1]);
      if (o[0] === value) { opt.selected = true; opt.setAttribute("selected", ""); }
      s.appendChild(opt);
    });
    s.addEventListener("change", function () { onChange(s.value); });
    wrap.appendChild(s);
    return wrap;
  }
  function densityOptions() {
    return [["all", "all densities"]].concat(world().cells.map(function (c) {
      return [dtext(c.density), dtext(c.density)];
    }));
  }
  function buildControls() {
    const box = document.getElementById("controls");
    box.textContent = "";
    box.appendChild(select("world", "cell group", D.worlds.map(function (w, i) {
      return [String(i), w.title];
    }), String(state.world), function (v) {
      state.world = Number(v);
      if (!world().cells.some(function (c) { return dtext(c.density) === state.density; })) state.density = "all";
      buildControls(); draw();
    }));
    box.appendChild(select("density", "obstacle density", densityOptions(), state.density,
      function (v) { state.density = v; draw(); }));
    box.appendChild(select("metric", "metric", D.metrics.map(function (m) {
      return [m, metricTitle(m)];
    }), state.metric, function (v) { state.metric = v; draw(); }));
    const pwrap = el("div", {class: "field"});
    const buttons = el("div", {class: "buttons"});
    const all = el("button", {type: "button", id: "all-planners"}, "all planners");
    const none = el("button", {type: "button", id: "no-planners"}, "none");
    all.addEventListener("click", function () { state.planners = D.planners.map(function (p) { return p.label; }); buildControls(); draw(); });
    none.addEventListener("click", function () { state.planners = []; buildControls(); draw(); });
    buttons.appendChild(all); buttons.appendChild(none);
    pwrap.appendChild(buttons);
    const list = el("div", {id: "planner-box"});
    D.planners.forEach(function (p) {
      const lab = el("label");
      const cb = el("input", {type: "checkbox", value: p.label});
      cb.checked = state.planners.indexOf(p.label) >= 0;
      cb.addEventListener("change", function () {
        state.planners = D.planners.map(function (q) { return q.label; }).filter(function (l) {
          return l === p.label ? cb.checked : state.planners.indexOf(l) >= 0;
        });
        draw();
      });
      const sw = el("span", {class: "swatch"});
      sw.style.background = p.colour;
      lab.appendChild(cb); lab.appendChild(sw);
      lab.appendChild(document.createTextNode(p.label + (p.label === D.baseline ? " (baseline)" : "")));
      list.appendChild(lab);
    });
    pwrap.appendChild(list);
    box.appendChild(pwrap);
  }

  // --- charts --------------------------------------------------------------------------------
  function logAxis(values, spread) {
    const v = values.filter(function (x) { return x !== null && isFinite(x); });
    if (!v.length || v.some(function (x) { return x <= 0; })) return false;
    return Math.max.apply(null, v) / Math.min.apply(null, v) > (spread || 30);
  }
  function layout(ytitle, extra) {
    return Object.assign({margin: {t: 36, r: 10, b: 50, l: 70}, height: 440,
      xaxis: {title: {text: "obstacle density"}, type: "category"},
      yaxis: {title: {text: ytitle}, automargin: true},
      legend: {orientation: "v", x: 1.02, y: 1, xanchor: "left"}, hovermode: "closest"}, extra || {});
  }
  function plot(id, traces, lay) {
    const div = document.getElementById(id);
    div.setAttribute("data-traces", String(traces.length));
    return Plotly.react(div, traces, lay, CONFIG).then(function () {
      div.setAttribute("data-drawn", String(Number(div.getAttribute("data-drawn") || 0) + 1));
    });
  }

  function drawBox() {
    const m = state.metric, title = metricTitle(m), runs = D.has_runs;
    const traces = [], all = [];
    chosen().forEach(function (label) {
      const p = PLANNER[label];
      const base = {type: "box", name: plotlyText(label), legendgroup: label, marker: {color: p.colour, symbol: symbol(label), size: 4},
        line: {color: p.colour, width: 1.5}, fillcolor: p.colour + "55", boxmean: true,
        hoverlabel: {namelength: -1}};
      if (runs) {
        const x = [], y = [];
        cells().forEach(function (c) {
          const vals = own(own(c.runs, label), m) || [];
          vals.forEach(function (v) { x.push(dtext(c.density)); y.push(v); all.push(v); });
        });
        if (y.length) traces.push(Object.assign(base, {x: x, y: y, boxpoints: "outliers"}));
      } else {
        const x = [], q1 = [], med = [], q3 = [], lo = [], hi = [], mean = [];
        cells().forEach(function (c) {
          const s = own((own(c.planners, label) || {}).m, m);
          if (!s || s.median === null || s.p5 === null) return;
          x.push(dtext(c.density)); q1.push(s.p5); med.push(s.median); q3.push(s.p95);
          lo.push(s.min); hi.push(s.max); mean.push(s.mean);
          all.push(s.min, s.max);
        });
        if (x.length) traces.push(Object.assign(base, {x: x, q1: q1, median: med, q3: q3,
          lowerfence: lo, upperfence: hi, mean: mean}));
      }
    });
    const lay = layout(title, {boxmode: "group"});
    if (logAxis(all)) { lay.yaxis.type = "log"; lay.yaxis.dtick = "D2"; }
    document.getElementById("box-title").textContent = "Distribution: " + title + " \u2014 " + world().title;
    document.getElementById("box-note").textContent = runs
      ? "Every run (metrics: successful runs; planning time: every run). Box: quartiles; whiskers: 1.5 IQR; points beyond; dashed: mean."
      : "From the report's summaries (give html_report.py --runs for every run): box p5\u2013p95, line median, whiskers min\u2013max, dashed: mean.";
    return plot("box-chart", traces, lay);
  }

  function drawSuccess() {
    const traces = [];
    chosen().forEach(function (label) {
      const p = PLANNER[label];
      const x = [], y = [], up = [], down = [], text = [];
      cells().forEach(function (c) {
        const s = own(c.planners, label);
        if (!s || !s.runs) return;
        const r = 100 * s.successes / s.runs;
        x.push(dtext(c.density)); y.push(r);
        up.push(s.ci[1] === null ? 0 : Math.max(0, 100 * s.ci[1] - r));
        down.push(s.ci[0] === null ? 0 : Math.max(0, r - 100 * s.ci[0]));
        const f = Object.keys(s.failures).map(function (k) { return k + " " + s.failures[k]; }).join(", ");
        text.push(s.successes + " / " + s.runs + (f ? " (" + f + ")" : ""));
      });
      if (x.length) traces.push({type: "bar", name: plotlyText(label), x: x, y: y, marker: {color: p.colour},
        error_y: {type: "data", array: up, arrayminus: down, visible: true, color: "#333", thickness: 1},
        text: text, hovertemplate: plotlyText(label) + "<br>density %{x}: %{y:.1f}%<br>%{text}<extra></extra>", textposition: "none"});
    });
    return plot("success-chart", traces, layout("success (% of runs)", {barmode: "group",
      yaxis: {title: {text: "success (% of runs)"}, range: [0, 102]}}));
  }

  function drawPaired() {
    const m = state.metric, traces = [], all = [];
    const others = chosen().filter(function (l) { return l !== D.baseline; });
    const ds = cells().map(function (c) { return c.density; });
    const n = Math.max(1, others.length), width = 0.8;
    others.forEach(function (label, k) {
      const p = PLANNER[label];
      const x = [], y = [], up = [], down = [], text = [];
      cells().forEach(function (c, i) {
        const comp = own(own(c.paired, label), m);
        if (!comp || comp.gm === null) return;
        x.push(i - width / 2 + width * (k + 0.5) / n); y.push(comp.gm);
        up.push(comp.ci95[1] === null ? 0 : Math.max(0, comp.ci95[1] - comp.gm));
        down.push(comp.ci95[0] === null ? 0 : Math.max(0, comp.gm - comp.ci95[0]));
        all.push(comp.gm, comp.ci95[0], comp.ci95[1]);
        text.push("density " + c.density + ": " + fmt(comp.gm) + " [" + fmt(comp.ci95[0]) + ", " + fmt(comp.ci95[1]) + "], " +
          fmtP(comp.p) + "<br>" + comp.pairs + " pairs: " + comp.wins + " better, " + comp.ties + " ties, " +
          comp.losses + " worse (" + comp.better + " is better)");
      });
      if (x.length) traces.push({type: "scatter", mode: "markers", name: plotlyText(label), x: x, y: y,
        marker: {color: p.colour, symbol: symbol(label), size: 9},
        error_y: {type: "data", array: up, arrayminus: down, visible: true, color: p.colour, thickness: 1.2},
        text: text, hovertemplate: plotlyText(label) + " / " + plotlyText(D.baseline) + "<br>%{text}<extra></extra>"});
    });
    const lay = layout("ratio to " + plotlyText(D.baseline), {
      xaxis: {title: {text: "obstacle density"}, tickvals: ds.map(function (_, i) { return i; }),
              ticktext: ds.map(dtext), range: [-0.6, ds.length - 0.4], zeroline: false},
      shapes: [{type: "line", xref: "paper", x0: 0, x1: 1, y0: 1, y1: 1, line: {dash: "dash", color: "#333"}}]});
    if (logAxis(all.concat([1]), 2.5)) { lay.yaxis.type = "log"; lay.yaxis.dtick = "D2"; }
    const title = metricTitle(state.metric);
    document.getElementById("paired-title").textContent = "Paired ratio to " + D.baseline + ": " + title;
    document.getElementById("paired-note").textContent = traces.length
      ? "Per map planner / " + D.baseline + " on the maps where both succeeded (planning time: every map both ran); marker: geometric mean, bar: 95% interval; hover: Wilcoxon p-value, wins/ties/losses. Below 1: smaller."
      : "No paired comparison of this metric for the chosen planners (the baseline itself, or a metric the report does not pair).";
    return plot("paired-chart", traces, lay);
  }

  function drawTable() {
    const m = state.metric, box = document.getElementById("table");
    box.textContent = "";
    document.getElementById("table-title").textContent = metricTitle(m) + ": mean [95% CI]; ratio to " + D.baseline + " (Wilcoxon p)";
    const t = el("table", {class: "values", id: "values-table"});
    const head = el("tr");
    head.appendChild(el("th", {}, "planner"));
    cells().forEach(function (c) { head.appendChild(el("th", {}, "density " + c.density)); });
    t.appendChild(head);
    chosen().forEach(function (label) {
      const tr = el("tr");
      tr.appendChild(el("td", {}, label + (label === D.baseline ? " (baseline)" : "")));
      cells().forEach(function (c) {
        const s = own((own(c.planners, label) || {}).m, m);
        const comp = own(own(c.paired, label), m);
        let text = s ? fmt(s.mean) + (s.ci95[0] !== null ? " [" + fmt(s.ci95[0]) + ", " + fmt(s.ci95[1]) + "]" : "") : "\u2013";
        if (comp && comp.gm !== null) text += "; \u00d7" + fmt(comp.gm) + " (" + fmtP(comp.p) + ")";
        const td = el("td", comp && comp.p !== null && comp.p < 0.05 ? {class: "sig"} : {}, text);
        tr.appendChild(td);
      });
      t.appendChild(tr);
    });
    box.appendChild(t);
  }

  function draw() {
    writeHash();
    drawTable();
    return Promise.all([drawBox(), drawSuccess(), drawPaired()]).then(function () {
      document.body.setAttribute("data-ready", "1");
    }).catch(function (e) { console.error("drawing failed: " + e); });
  }

  document.getElementById("title").textContent = "agvbench sweep: " + D.name;
  const env = D.environment || {};
  document.getElementById("meta").textContent = "seed " + D.seed + ", " + D.maps_per_cell + " maps per cell, " +
    D.planners.length + " planners, baseline " + D.baseline + (D.complete === false ? " \u2014 INCOMPLETE sweep" : "") +
    (env.cpu_model ? "; " + env.cpu_model + ", " + env.threads + " threads, revision " + env.git_revision : "") +
    (env.date_utc ? ", " + env.date_utc : "") + ". Times in \u00b5s.";
  readHash();
  buildControls();
  draw();
})();

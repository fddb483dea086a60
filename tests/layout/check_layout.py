#!/usr/bin/python3
"""The source layout's rules beyond the folders' dependency rule (tests/layout/
check_dependencies.sh; docs/ARCHITECTURE.md "Dependency rule"), checked on the tree:

1. no include cycle between units (a unit is a file pair, x.h + x.cpp) within engine/, cli/ or
   algos/;
2. no file in reports/ edits sys.path (reports/ is a package its scripts import as it is);
3. no function in engine/ or cli/ longer than MAX_FUNCTION_LINES lines, signature to closing
   brace;
4. JSON is parsed only where JSON_PARSERS says, and a run record in one place per language:
   engine/outputs/run_record.cpp (JournalDecoder::decode_line) and reports/agvreports/runs.py
   (journal_records); a new parser of records would be a second codec (issue 46, stage 1).

Prints every violation, one per line, and exits 1 if there is any. Usage: check_layout.py ROOT"""
import os
import re
import sys

MAX_FUNCTION_LINES = 80
CYCLE_ROOMS = ("engine", "cli", "algos")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
# Where a file of the tree may parse JSON, and what it parses.
JSON_PARSERS = {
    "engine/outputs/run_record.cpp": "run records: journals and the isolated worker's channel",
    "engine/plan/config_loader.cpp": "sweep configs",
    "engine/sweep/isolated_worker.cpp": "the worker channel's control lines (config, ready, requests)",
    "cli/cli_params.cpp": "--param values",
    "cli/report_file.cpp": "reports (compare, digest)",
    "reports/agvreports/runs.py": "run records: journal_records",
    "reports/agvreports/report_io.py": "reports",
}
JSON_PARSE = re.compile(r"json::parse\(|json\.loads?\(")
CONTROL = re.compile(r"\b(if|for|while|switch|catch|do|else)\s*(\(|$)")


def sources(root, room):
    for folder, _, files in os.walk(os.path.join(root, room)):
        for name in sorted(files):
            if name.endswith((".h", ".cpp")):
                yield os.path.relpath(os.path.join(folder, name), root)


def unit_of(path):
    return os.path.splitext(path)[0]


def include_graph(root, rooms):
    graph = {}
    for room in rooms:
        for path in sources(root, room):
            with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
                text = f.read()
            edges = graph.setdefault(unit_of(path), set())
            for target in INCLUDE.findall(text):
                if target.split("/")[0] in rooms and os.path.exists(os.path.join(root, target)):
                    if unit_of(target) != unit_of(path):
                        edges.add(unit_of(target))
    return graph


def cycles(graph):
    """Strongly connected components of more than one unit (Tarjan, iterative)."""
    index, low, on_stack, stack, found = {}, {}, set(), [], []
    for start in sorted(graph):
        if start in index:
            continue
        work = [(start, iter(sorted(graph.get(start, ()))))]
        index[start] = low[start] = len(index)
        stack.append(start)
        on_stack.add(start)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = len(index)
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(graph.get(child, ())))))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    top = stack.pop()
                    on_stack.discard(top)
                    component.append(top)
                    if top == node:
                        break
                if len(component) > 1:
                    found.append(sorted(component))
    return found


def blank_out(text):
    """Comments, string and character literals replaced by spaces (newlines kept)."""
    pattern = re.compile(r'//[^\n]*|/\*.*?\*/|R"([^(]*)\(.*?\)\1"|"(?:\\.|[^"\\\n])*"|'
                         r"'(?:\\.|[^'\\\n])*'", re.S)
    return pattern.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)


def long_functions(path, text):
    """(line, length) of each outermost function body longer than MAX_FUNCTION_LINES."""
    code = blank_out(text)
    found = []
    depth = 0
    function_depth = None  # brace depth at which the current function's body opened
    start_line = 0
    head_start = 0  # where the text before the current brace began
    for i, ch in enumerate(code):
        if ch in ";}" and function_depth is None:
            head_start = i + 1
        if ch == "{":
            head = code[head_start:i]
            if function_depth is None and ")" in head and not CONTROL.search(head.strip()):
                function_depth = depth
                first = len(head) - len(head.lstrip())
                start_line = code.count("\n", 0, head_start + first) + 1
            depth += 1
            if function_depth is None:
                head_start = i + 1
        elif ch == "}":
            depth -= 1
            if function_depth is not None and depth == function_depth:
                end_line = code.count("\n", 0, i) + 1
                if end_line - start_line + 1 > MAX_FUNCTION_LINES:
                    found.append((start_line, end_line - start_line + 1))
                function_depth = None
                head_start = i + 1
    return found


def main(root):
    problems = []
    rooms = tuple(r for r in CYCLE_ROOMS if os.path.isdir(os.path.join(root, r)))
    for component in cycles(include_graph(root, rooms)):
        problems.append("include cycle: " + " -> ".join(component))
    for folder, _, files in os.walk(os.path.join(root, "reports")):
        for name in sorted(files):
            if name.endswith(".py"):
                path = os.path.join(folder, name)
                with open(path, encoding="utf-8") as f:
                    if "sys.path" in f.read():
                        problems.append(f"{os.path.relpath(path, root)} edits sys.path")
    for room in ("engine", "cli"):
        for path in sources(root, room):
            with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
                for line, length in long_functions(path, f.read()):
                    problems.append(f"{path}:{line}: function of {length} lines "
                                    f"(at most {MAX_FUNCTION_LINES})")
    for room in ("engine", "cli", "algos", "core", "generators", "reports"):
        for folder, _, files in os.walk(os.path.join(root, room)):
            for name in sorted(files):
                if not name.endswith((".h", ".cpp", ".py")):
                    continue
                path = os.path.relpath(os.path.join(folder, name), root)
                with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
                    if JSON_PARSE.search(f.read()) and path not in JSON_PARSERS:
                        problems.append(f"{path} parses JSON: records are decoded by "
                                        "engine/outputs/run_record.cpp or reports/agvreports/runs.py "
                                        "(add others to JSON_PARSERS with what they parse)")
    for p in problems:
        print(p)
    print(f"check_layout: {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))

"""tools/mutate.sh's helper: reads the list of rule files, prepares each one's copy of the
project, and turns gdmutant's reports into the table (build/mutate/table.md).

  mutate_lists.py targets TARGETS [FILE...]         the list's lines, as FILE|FUNCS|TESTS
  mutate_lists.py prepare COPY FILE FUNCS TEST...   keeps only TEST... in COPY's tests and, when
                                                    FUNCS is given, marks every other line of
                                                    FILE out of scope; prints the tests kept
  mutate_lists.py reports TARGETS OUT                the reports in OUT, in the list's order
  mutate_lists.py table EQUIVALENTS REPORT.json...  the table, in Markdown
"""

import json
import os
import re
import sys
from pathlib import Path

OUT_OF_SCOPE = "  # gdmutant: ignore out of scope (tools/mutate/targets.txt)"
TEST_DIRS = ("tests/unit", "tests/integration")


def read_targets(path):
    """[(file, [functions], [tests])] in the list's order."""
    targets = []
    for number, raw in enumerate(Path(path).read_text().splitlines(), start=1):
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        left, sep, right = line.partition(" : ")
        match = re.fullmatch(r"(\S+)(?:\s+\[([^\]]*)\])?", left.strip())
        if not sep or match is None:
            sys.exit(f"{path}:{number}: not 'RULE_FILE [FUNCTIONS] : TEST_FILE...'")
        functions = (match.group(2) or "").split()
        targets.append((match.group(1), functions, right.split()))
    return targets


def cmd_targets(path, wanted):
    for file, functions, tests in read_targets(path):
        if wanted and not any(w == file or w.rstrip("/") == file or os.path.basename(w) == os.path.basename(file) for w in wanted):
            continue
        print(f"{file}|{' '.join(functions)}|{' '.join(tests)}")


def cmd_reports(path, out):
    for file, _functions, _tests in read_targets(path):
        report = Path(out) / (Path(file).stem + ".json")
        if report.is_file():
            print(report)


def function_lines(source_lines, functions):
    """1-based line numbers inside the named top-level functions (signature to last line)."""
    inside = set()
    current = None
    for number, line in enumerate(source_lines, start=1):
        match = re.match(r"(?:static\s+)?func\s+(\w+)\s*\(", line)
        if match:
            current = match.group(1) if match.group(1) in functions else None
        elif line and not line[0].isspace() and not line.startswith("#"):
            current = None  # a top-level line ends the function above it
        if current is not None:
            inside.add(number)
    return inside


def mark_out_of_scope(path, functions):
    lines = path.read_text().split("\n")
    found = {m.group(1) for m in (re.match(r"(?:static\s+)?func\s+(\w+)\s*\(", l) for l in lines) if m}
    missing = [f for f in functions if f not in found]
    if missing:  # an older tree (MUTATE_FROM) may not have them yet
        print(f"mutate: {path.name} has no function {', '.join(missing)}", file=sys.stderr)
    inside = function_lines(lines, functions)
    in_string = False
    for index, line in enumerate(lines):
        quotes = line.count('"""') % 2 == 1
        code = line.strip()
        bare = code and not code.startswith("#") and not code.endswith("\\")
        if not in_string and not quotes and index + 1 not in inside and bare:
            lines[index] = line + OUT_OF_SCOPE
        if quotes:
            in_string = not in_string
    path.write_text("\n".join(lines))


def cmd_prepare(copy, file, functions, tests):
    copy = Path(copy)
    kept = [t for t in tests if (copy / t).is_file()]
    keep = {str(copy / t) for t in kept}
    for folder in TEST_DIRS:
        for test in (copy / folder).rglob("test_*.gd"):
            if str(test) not in keep:
                test.unlink()
                Path(str(test) + ".uid").unlink(missing_ok=True)
    if functions.split():
        mark_out_of_scope(copy / file, functions.split())
    print(" ".join(kept))


def load_equivalents(path):
    """{(file, source line, original, replacement): reason}. ORIGINAL may end in @COLUMN
    (gdmutant's, from 1) where the line holds the same text more than once."""
    known = {}
    if not Path(path).is_file():
        return known
    for number, raw in enumerate(Path(path).read_text().splitlines(), start=1):
        if not raw.strip() or raw.lstrip().startswith("#"):
            continue
        parts = [p.strip() for p in raw.split(" | ")]
        change = parts[2].split(" -> ") if len(parts) == 4 else []
        if len(change) != 2 or not parts[3]:
            sys.exit(f"{path}:{number}: not 'FILE | SOURCE LINE | ORIGINAL -> REPLACEMENT | REASON'")
        known[(parts[0], parts[1], change[0], change[1])] = parts[3]
    return known


def span_text(source_lines, location):
    start, end = location["start"], location["end"]
    if start["line"] == end["line"]:
        return source_lines[start["line"] - 1][start["column"] - 1 : end["column"] - 1]
    return source_lines[start["line"] - 1][start["column"] - 1 :].strip() + " ..."


def describe(text):
    text = " ".join(text.split())
    return text if len(text) <= 40 else text[:37] + "..."


def cmd_table(equivalents_path, reports):
    equivalents = load_equivalents(equivalents_path)
    used = set()
    rows = []
    details = []
    for report in reports:
        data = json.loads(Path(report).read_text())
        scope_path = Path(report).with_suffix(".scope")
        functions = scope_path.read_text().rstrip("\n").split("\t")[1] if scope_path.is_file() else ""
        for file, entry in data["files"].items():
            source_lines = entry["source"].split("\n")
            file = file.removeprefix("./")
            counts = {"killed": 0, "survived": 0, "suppressed": 0, "not run": 0}
            survivors = []
            for mutant in entry["mutants"]:
                status = mutant["status"]
                if status in ("Killed", "Timeout"):
                    counts["killed"] += 1
                    continue
                if status not in ("Survived", "NoCoverage"):
                    counts["not run"] += 1  # out of scope, invalid, error
                    continue
                location = mutant["location"]
                line = location["start"]["line"]
                source = source_lines[line - 1].split(OUT_OF_SCOPE)[0].strip()
                original = span_text(source_lines, location)
                replacement = mutant.get("replacement", "")
                key = (file, source, describe(original), describe(replacement))
                column = location["start"]["column"]
                at_column = (file, source, f"{describe(original)}@{column}", describe(replacement))
                found = next((k for k in (at_column, key) if k in equivalents), None)
                if found is not None:
                    counts["suppressed"] += 1
                    used.add(found)
                    continue
                counts["survived"] += 1
                survivors.append((line, mutant["mutatorName"], original, replacement, source))
            total = counts["killed"] + counts["survived"]
            score = f"{100.0 * counts['killed'] / total:.0f} %" if total else "-"
            name = f"{file} ({functions})" if functions else file
            lines = ", ".join(f"L{s[0]}" for s in sorted(survivors))
            rows.append(f"| {name} | {total} | {counts['killed']} | {score} | {counts['suppressed']} | {lines or '-'} |")
            for line, mutator, original, replacement, source in sorted(survivors):
                details.append(
                    f"- `{file}:{line}` {mutator}: `{describe(original)}` -> `{describe(replacement)}`"
                    f"  (line: `{describe(source)}`)"
                )
                details.append(f"  equivalent? `{file} | {source} | {describe(original)} -> {describe(replacement)} | WHY`")
    print("| file (scope) | mutants | killed | score | equivalent | survivors (line) |")
    print("|---|---|---|---|---|---|")
    print("\n".join(rows))
    if details:
        print("\nSurvivors (an equivalent one goes into tools/mutate/equivalents.txt, with its reason):\n")
        print("\n".join(details))
    files_run = {row.split(" | ")[0].lstrip("| ").split(" (")[0] for row in rows}
    stale = [k for k in equivalents if k not in used and k[0] in files_run]
    if stale:
        print("\nEquivalents listed that no survivor matched (the code moved on?):\n")
        print("\n".join(f"- `{k[0]} | {k[1]} | {k[2]} -> {k[3]}`" for k in stale))


def main(argv):
    if len(argv) >= 2 and argv[0] == "targets":
        cmd_targets(argv[1], argv[2:])
    elif len(argv) == 3 and argv[0] == "reports":
        cmd_reports(argv[1], argv[2])
    elif len(argv) >= 4 and argv[0] == "prepare":
        cmd_prepare(argv[1], argv[2], argv[3], argv[4:])
    elif len(argv) >= 2 and argv[0] == "table":
        cmd_table(argv[1], argv[2:])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv[1:])

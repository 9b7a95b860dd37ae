#!/usr/bin/env python3
"""Runs the examples of the documentation as a reader pastes them, so that they cannot rot.

  lua WRC PAGE --marker=MARKER [--expect REGEX] --tmp DIR [--args K=V ...]
      The ```lua block of PAGE whose first line starts with MARKER (`-- first.lua`) is written to a fresh folder
      DIR/<its name> and run there by `WRC run <name> K=V ...`. It must exit 0, its output must match REGEX, and where
      the page shows what it prints -- a ```text block whose first line is the command, `$ ... wrc run <name> ...` --
      the output must be that block: the same words, and each number the same to within one unit of its last printed
      digit (a build's rounding may move a solver's last bits, never a printed figure by more).
  python INTERPRETER PAGE ... --tmp DIR
      Every ```python block of the pages runs on its own, in a fresh folder, with INTERPRETER (PYTHONPATH from the
      environment); each must exit 0 and print a figure.
  keys ROOT
      Every key of a call in the ```lua blocks of README.md and docs/ (`ws:contact{y = ..., mu = ...}`,
      `wrc.wheelset{...}`, `tr:wheel{...}`) is a key the call takes: the engine's own list of each call's options,
      `wrc.operations()` (run with the package on PYTHONPATH), so that a misspelt or renamed key in an example fails.

Prints what ran and why it failed; exits 1 on the first failure.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def blocks(text, language):
    """(line, content) of every fenced block of the language; line: the 1-based line of its first line of content."""
    found, lines, i = [], text.split("\n"), 0
    while i < len(lines):
        if lines[i].strip() == "```" + language:
            start, body = i + 2, []
            i += 1
            while i < len(lines) and not lines[i].startswith("```"):
                body.append(lines[i])
                i += 1
            found.append((start, "\n".join(body) + "\n"))
        i += 1
    return found


def fresh(folder):
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    return folder


def same_figures(shown, printed):
    """'' when the printed lines are the shown ones (numbers within one unit of the last shown digit), else why not."""
    want, got = shown.strip().split("\n"), printed.strip().split("\n")
    if len(want) != len(got):
        return f"{len(got)} lines printed, the page shows {len(want)}"
    for k, (w, g) in enumerate(zip(want, got), 1):
        if NUMBER.sub("#", w).split() != NUMBER.sub("#", g).split():
            return f"line {k}: printed '{g}', the page shows '{w}'"
        for a, b in zip(NUMBER.findall(w), NUMBER.findall(g)):
            mantissa = re.split(r"[eE]", a)[0]
            unit = 10.0 ** -(len(mantissa.split(".")[1]) if "." in mantissa else 0)
            if "e" in a.lower():
                unit *= 10.0 ** int(re.split(r"[eE]", a)[1])
            if abs(float(a) - float(b)) > unit * 1.0000001:
                return f"line {k}: printed {b} where the page shows {a}: '{g}'"
    return ""


def run_lua(args):
    text = open(args.page, encoding="utf-8").read()
    found = [b for _, b in blocks(text, "lua") if b.startswith(args.marker)]
    if not found:
        sys.exit(f"{args.page} has no ```lua block starting with '{args.marker}'")
    name = re.search(r"[A-Za-z0-9_]+\.lua", args.marker).group(0)
    folder = fresh(os.path.join(args.tmp, name[:-4]))
    with open(os.path.join(folder, name), "w", encoding="utf-8") as f:
        f.write(found[0])
    wrc = os.path.abspath(args.wrc) if os.sep in args.wrc else args.wrc   # it runs in the example's folder
    run = subprocess.run([wrc, "run", name] + args.args, cwd=folder, capture_output=True, text=True)
    print(run.stdout + run.stderr)
    if run.returncode != 0:
        sys.exit(f"{name} from {args.page} failed ({run.returncode})")
    if args.expect and not re.search(args.expect, run.stdout + run.stderr, flags=re.S):
        sys.exit(f"{name} from {args.page} ran, but its output does not match '{args.expect}'")
    for line, shown in blocks(text, "text"):
        first, _, rest = shown.partition("\n")
        if first.startswith("$ ") and re.search(r"\bwrc run " + re.escape(name) + r"\b", first):
            why = same_figures(rest, run.stdout)
            if why:
                sys.exit(f"{args.page}:{line}: {name} no longer prints what the page shows: {why}")
            print(f"{args.page}:{line}: printed as shown")


def run_python(args):
    count = 0
    for page in args.pages:
        for line, code in blocks(open(page, encoding="utf-8").read(), "python"):
            folder = fresh(os.path.join(args.tmp, f"{os.path.basename(page)[:-3]}_{line}"))
            run = subprocess.run([args.interpreter, "-c", code], cwd=folder, capture_output=True, text=True)
            print(f"{page}:{line}:\n{run.stdout}{run.stderr}")
            if run.returncode != 0:
                sys.exit(f"{page}:{line}: the Python example fails ({run.returncode})")
            if not re.search(r"\d", run.stdout):
                sys.exit(f"{page}:{line}: the Python example runs but prints no figure")
            count += 1
    print(f"{count} Python examples ran")


# The receivers the examples give each kind of object (ws = wrc.wheelset{...}, wp the planar one, tr a trajectory).
RECEIVERS = {"ws": "wheelset", "wp": "wheelset", "tr": "trajectory"}
# Keys a call reads outside its options list: the profiles of a wheelset.
PROFILE_KEYS = {"wheel", "rail", "left_wheel", "right_wheel", "left_rail", "right_rail"}


def top_level_keys(code, start):
    """The `key =` names of the table that opens at code[start - 1] == '{', nested tables left out."""
    depth, flat, i = 1, [], start
    while i < len(code) and depth:
        depth += {"{": 1, "}": -1}.get(code[i], 0)
        if depth == 1 and code[i] != "}":
            flat.append(code[i])
        i += 1
    return re.findall(r"(?:^|[,\s])([A-Za-z_]\w*)\s*=(?!=)", "".join(flat))


def check_keys(args):
    import glob
    import wrc
    calls = {o["lua"]: {opt["key"].split(".")[0] for opt in o["options"]} for o in wrc.operations()}
    calls["wrc.wheelset"] |= PROFILE_KEYS
    pages = [os.path.join(args.root, "README.md")] + sorted(glob.glob(os.path.join(args.root, "docs/**/*.md"),
                                                                        recursive=True))
    bad, count = [], 0
    for page in pages:
        for line, code in blocks(open(page, encoding="utf-8").read(), "lua"):
            code = re.sub(r"--[^\n]*", "", code)                                   # comments
            code = re.sub(r'"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'', '""', code)   # strings
            for m in re.finditer(r"\b(wrc|ws|wp|tr)([:.])(\w+)\s*\{", code):
                receiver, sep, method = m.groups()
                call = f"wrc.{method}" if receiver == "wrc" else f"{RECEIVERS[receiver]}:{method}"
                if call not in calls or sep != (":" if receiver != "wrc" else "."):
                    continue
                count += 1
                at = line + code[:m.start()].count("\n")
                bad += [f"{page}:{at}: {call} takes no key '{k}'" for k in top_level_keys(code, m.end())
                        if k not in calls[call]]
    print("\n".join(bad) or f"{count} calls of the Lua examples checked: every key exists")
    if bad:
        sys.exit(1)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="kind", required=True)
    lua = sub.add_parser("lua")
    lua.add_argument("wrc")
    lua.add_argument("page")
    lua.add_argument("--marker", required=True)  # given as --marker=..., it starts with "--"
    lua.add_argument("--args", nargs="*", default=[])
    lua.add_argument("--expect", default="")
    lua.add_argument("--tmp", required=True)
    py = sub.add_parser("python")
    py.add_argument("interpreter")
    py.add_argument("pages", nargs="+")
    py.add_argument("--tmp", required=True)
    keys = sub.add_parser("keys")
    keys.add_argument("root")
    args = parser.parse_args()
    {"lua": run_lua, "python": run_python, "keys": check_keys}[args.kind](args)


if __name__ == "__main__":
    main()

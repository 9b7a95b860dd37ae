#!/usr/bin/env python3
"""Checks that what the documentation cites exists, so that it cannot drift from the code unnoticed.

In README.md and the pages of docs/ (outside fenced code blocks):
  - every repository path in backticks exists: `engine/src/...`, `tests/...`, `scripts/...`, `examples/...`,
    `profiles/...`, `plugins/...`, `docs/...`, `cmake/...`, `.ci/...`, `matlab/...`; include paths `wrc/...`; area-relative ones
    (`halfspace/normal_cg.cpp`, `wheelset/conformal`) under engine/src or engine/include/wrc; benchmark programs
    (`build/bench_normal`, `bench_rolling`) under tests/bench; bare source file names (`conformal_contact.lua`)
    somewhere in the tree. `<name>`, `*` and ALL-CAPS components are placeholders;
  - every code name in backticks that looks like the engine's (`solve_wheel`, `ContactRequest::rolling`,
    `wrc_contact`, `NormalLoad::gap_weights`, `ws:contact`, `wrc.profile.load`, `e.left.flange_climb`) appears in
    the code (comments stripped) of engine/, scripts/, plugins/, examples/, profiles/, matlab/ or the build files; a
    qualified C++ name needs its class and member in one file;
  - every relative link and image exists, every #anchor names a heading of its page as both mkdocs and GitHub spell
    it, and pages of docs/ link nowhere outside docs/ (the site could not follow);
  - README.md has at most 300 lines, its set-up commands are those of docs/getting-started.md and its paper-to-code
    table is the one of docs/paper.md; every page of docs/ is in the nav of mkdocs.yml (the site reaches it).
In the sources (engine/, scripts/, plugins/, examples/, tests/, cmake/, .ci/, matlab/): every cited section exists --
README "Title", docs/<page>.md "Title" (a heading that starts so), docs/design.md section N -- and every cited
docs/ page.

Usage: check_docs.py ROOT [--pages FILE...] [--sources FILE...]: without --pages, README.md and docs/**/*.md, with
the README checks; without --sources, every source file. Prints file:line: problem, exits 1 when there is one.
"""
import argparse
import glob
import os
import re
import sys
import unicodedata

TOP = ("engine", "tests", "scripts", "examples", "profiles", "plugins", "docs", "cmake", ".ci", "matlab", "python")
SOURCE_EXT = (".cpp", ".hpp", ".h", ".c", ".lua", ".sh", ".cmake", ".py", ".sbatch", ".in", ".map", ".m")
CODE_DIRS = ("engine", "scripts", "plugins", "examples", "profiles", "cmake", ".ci", "matlab", "python")
# Names used in the docs as illustrations, not files or code of the repository.
ILLUSTRATIVE = {"first.lua", "yq.lua", "my_wheel.lua", "my_walk.lua", "my_strategy.lua", "zz.lua",
                "scripts/x/y.lua", "scripts/strategies/my_walk.lua"}
# Names the docs use that are not wrc's code: other libraries' (MuJoCo, numpy, C) and mathematical symbols.
NOT_CODE = {"mjModel", "mjData", "numpy.loadtxt", "SIZE_MAX", "e_x", "mu_s", "mu_k", "TypeError"}
# Files made when wrc runs or builds (outputs, generated headers), not files of the repository.
DATA_EXT = ("txt", "csv", "png", "md", "h", "hpp", "cpp", "c", "lua", "so", "pc", "sh", "gp", "dat", "py", "sbatch",
            "toml")
GENERATED = {"config.hpp"}
# Short names that are Lua receivers in the docs' examples (ws:contact, e.left, ...), not engine names.
MAX_RECEIVER = 3

problems = []


def report(path, line, message):
    problems.append(f"{path}:{line}: {message}")


# ---- the repository -------------------------------------------------------------------------------------------

class Tree:
    def __init__(self, root):
        self.root = root
        self.files = []
        for base, dirs, names in os.walk(root):
            dirs[:] = [d for d in dirs if not d.startswith("build") and d not in (".git", "site")]
            for n in names:
                self.files.append(os.path.relpath(os.path.join(base, n), root))
        self.basenames = {os.path.basename(f) for f in self.files}
        self.areas = sorted({p.split("/")[2] for p in self.files if p.startswith("engine/src/")
                             and p.count("/") >= 3} |
                            {p.split("/")[3] for p in self.files if p.startswith("engine/include/wrc/")
                             and p.count("/") >= 4})
        self.tokens, self.file_tokens = self._code_tokens()

    def exists(self, rel):
        """rel exists (file or folder); placeholders (<x>, *, ALL-CAPS components) match anything."""
        rel = rel.rstrip("/")
        parts = [("*" if ("<" in c or "*" in c or (c.isupper() and len(c) > 1) or c in ("K", "N")) else c)
                 for c in rel.split("/")]
        pattern = "/".join(re.sub(r"<[^>]*>", "*", p) for p in parts)
        if "*" not in pattern:
            return os.path.exists(os.path.join(self.root, pattern))
        return bool(glob.glob(os.path.join(self.root, pattern)))

    def _code_tokens(self):
        tokens, per_file = set(), {}
        for f in self.files:
            top = f.split("/")[0]
            build_file = f.endswith("CMakeLists.txt") or f.endswith(".cmake")
            if not (top in CODE_DIRS or f in ("CMakeLists.txt", "setup.py") or (top == "tests" and build_file)
                    or f.startswith(("tests/bench/", "tests/fuzz/"))):
                continue
            if not (f.endswith(SOURCE_EXT) or build_file or "/" not in f.split(".ci/")[-1]):
                continue
            try:
                text = open(os.path.join(self.root, f), encoding="utf-8", errors="replace").read()
            except OSError:
                continue
            words = set(re.findall(r"[A-Za-z_][A-Za-z0-9_]*", strip_comments(f, text)))
            per_file[f] = words
            tokens |= words
        return tokens, per_file


def strip_comments(path, text):
    """The code of a source file without its comments (string literals kept: option keys and field names)."""
    if path.endswith((".cpp", ".hpp", ".h", ".c")):
        pattern = r'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\''
        return re.sub(pattern, lambda m: m.group(0) if m.group(0)[0] in "\"'" else " ", text, flags=re.S)
    if path.endswith(".lua"):
        pattern = r'--\[(=*)\[.*?\]\1\]|--[^\n]*|\[(=*)\[.*?\]\2\]|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\''
        return re.sub(pattern, lambda m: " " if m.group(0).startswith("--") else m.group(0), text, flags=re.S)
    if path.endswith(".m"):  # MATLAB: % comments; strings in quotes kept
        pattern = r"'(?:''|[^'\n])*'|\"(?:\"\"|[^\"\n])*\"|%[^\n]*"
        return re.sub(pattern, lambda m: " " if m.group(0).startswith("%") else m.group(0), text)
    return re.sub(r"(?m)(^|\s)#[^\n]*", " ", text)


# ---- markdown -------------------------------------------------------------------------------------------------

def without_fences(text):
    """The text with fenced code blocks blanked (line numbers kept)."""
    out, fence = [], None
    for line in text.split("\n"):
        m = re.match(r"^\s*(```+|~~~+)", line)
        if fence is None and m:
            fence = m.group(1)[:3]
            out.append("")
        elif fence is not None:
            if line.strip().startswith(fence):
                fence = None
            out.append("")
        else:
            out.append(line)
    return "\n".join(out)


def code_spans(text):
    """(offset, content) of the inline code spans of a text without fences; a span stays inside a paragraph."""
    for m in re.finditer(r"(?<!`)(`+)(?!`)((?:(?!\n\s*\n).)+?)(?<!`)\1(?!`)", text, flags=re.S):
        yield m.start(), re.sub(r"\s+", " ", m.group(2)).strip()


def line_of(text, offset):
    return text.count("\n", 0, offset) + 1


def slug_mkdocs(title):
    value = unicodedata.normalize("NFKD", title).encode("ascii", "ignore").decode("ascii")
    value = re.sub(r"[^\w\s-]", "", value).strip().lower()
    return re.sub(r"[-\s]+", "-", value)


def slug_github(title):
    value = "".join(c for c in title.lower() if c.isalnum() or c in " -_")
    return value.replace(" ", "-")


def heading_text(raw):
    raw = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", raw)
    return re.sub(r"[`*]", "", raw).strip()


def headings(path):
    """The headings of a markdown file: [(line, text)]."""
    text = without_fences(open(path, encoding="utf-8").read())
    found = []
    for i, line in enumerate(text.split("\n"), 1):
        m = re.match(r"^(#{1,6})\s+(.*?)\s*#*\s*$", line)
        if m:
            found.append((i, heading_text(m.group(2))))
    return found


def anchors(path, slug):
    seen, ids = {}, set()
    for _, title in headings(path):
        s = slug(title)
        if s in seen:
            seen[s] += 1
            s = f"{s}_{seen[s]}" if slug is slug_mkdocs else f"{s}-{seen[s]}"
        else:
            seen[s] = 0
        ids.add(s)
    return ids


# ---- what a page cites ----------------------------------------------------------------------------------------

PATH_RE = re.compile(r"(?<![\w./<>-])((?:\.ci|engine|tests|scripts|examples|profiles|plugins|docs|cmake|python)/"
                     r"[\w./*<>-]*)")
NAME_RE = re.compile(r"^[A-Za-z_]\w*(?:(?:::|\.|:)[A-Za-z_]\w*)*(?:\(.*\)|\{.*\})?$", re.S)


def check_path_token(tree, page, line, token):
    token = token.rstrip(".,;:)")
    if token in ILLUSTRATIVE or not token:
        return
    if not tree.exists(token):
        report(page, line, f"cites `{token}`, which is not in the repository")


def check_area_path(tree, page, line, token):
    token = token.rstrip(".,;:)/")
    area, _, rest = token.partition("/")
    candidates = [f"engine/src/{area}/{rest}", f"engine/include/wrc/{area}/{rest}"]
    if not rest:
        candidates = [f"engine/src/{area}", f"engine/include/wrc/{area}"]
    elif "." not in os.path.basename(rest):
        candidates += [c + ext for c in candidates for ext in (".cpp", ".hpp", ".h")]
    if not any(tree.exists(c) for c in candidates):
        report(page, line, f"cites `{token}`, which is neither under engine/src nor engine/include/wrc")


def check_paths(tree, page, line, span):
    for m in PATH_RE.finditer(span):
        if span[max(0, m.start() - 2):m.start()] == "./":
            continue  # ./profiles/... is the working directory's, on purpose
        check_path_token(tree, page, line, m.group(1))
    for m in re.finditer(r"(?<![\w./<>-])wrc/([\w./]+\.h(?:pp)?)", span):
        check_path_token(tree, page, line, "engine/include/wrc/" + m.group(1))
    area_re = r"(?<![\w./<>-])((?:%s)/[\w./*<>-]*)" % "|".join(map(re.escape, tree.areas))
    for m in re.finditer(area_re, span):
        before = span[:m.start()]
        if re.search(r"(?:wrc|include|src|engine)/$", before):
            continue
        if m.group(1).split("/")[0] in TOP:
            continue  # a repository path (python/wrc), checked above
        check_area_path(tree, page, line, m.group(1))
    for m in re.finditer(r"(?<![\w/])build/(bench_\w+)", span):
        check_bench(tree, page, line, m.group(1))
    for m in re.finditer(r"(?<![\w./<>-])([\w-]+\.(?:cpp|hpp|h|c|lua|sh|cmake|py|sbatch))(?![\w/])", span):
        name = m.group(1)
        if name in ILLUSTRATIVE or name.split(".")[0].isupper() or span[:m.start()].endswith("/"):
            continue
        if name not in tree.basenames:
            report(page, line, f"cites `{name}`, which no file of the repository is called")


def check_bench(tree, page, line, name):
    if not (tree.exists(f"tests/bench/{name}.cpp") or tree.exists(f"tests/bench/{name}.sh")):
        report(page, line, f"cites the benchmark `{name}`, which tests/bench does not hold")


def check_name(tree, page, line, span):
    if not NAME_RE.match(span) or span in NOT_CODE:
        return
    name = re.sub(r"(\(.*\)|\{.*\})$", "", span, flags=re.S)
    parts = re.split(r"::|\.|:", name)
    if name.endswith("_") or (len(parts) == 2 and "::" not in name and parts[1] in DATA_EXT):
        return  # a brace expansion (rigid_vs_elastic_{z,roll}), a file name (sweep.csv: checked as a path)
    qualified = "::" in name
    if len(parts) == 1:
        word = parts[0]
        if re.fullmatch(r"(bench|test)_\w+", word):
            if not any(os.path.basename(f).split(".")[0] == word for f in tree.files if f.startswith("tests/")):
                report(page, line, f"cites `{word}`, which no file under tests/ is called")
            return
        if re.fullmatch(r"fuzz_reader_\w+", word):
            if not tree.exists("plugins/" + word[len("fuzz_reader_"):]):
                report(page, line, f"cites `{word}`, but no plugin of that name exists")
            return
        if not ("_" in word.strip("_") or re.search(r"[a-z][A-Z]", word) or word.startswith("wrc")):
            return  # a plain word (accurate, Track, Y): too common to mean anything
        if word not in tree.tokens:
            report(page, line, f"cites `{word}`, which the code of engine/, scripts/, plugins/, examples/ does not hold")
        return
    if qualified:
        names = [p for p in parts if p not in ("wrc", "std")]
        missing = [p for p in names if p not in tree.tokens]
        if missing:
            report(page, line, f"cites `{name}`, but the code does not hold {', '.join(missing)}")
        elif len(names) >= 2 and names[-2][0].isupper():
            if not any(names[-2] in w and names[-1] in w for w in tree.file_tokens.values()):
                report(page, line, f"cites `{name}`, but no file holds both {names[-2]} and {names[-1]}")
        return
    # Lua: wrc.module.call, receiver:method, receiver.field.path
    rest = parts[1:] if parts[0] == "wrc" or len(parts[0]) <= MAX_RECEIVER or parts[0].islower() else parts
    missing = [p for p in rest if p not in tree.tokens and not p.isdigit()]
    if missing:
        report(page, line, f"cites `{name}`, but the code does not hold {', '.join(missing)}")


def location_files(tree, loc):
    """The files a cited location stands for: a file, a folder's files, an area-relative path (with its header)."""
    loc = loc.rstrip("/")
    area, _, rest = loc.partition("/")
    if loc.split("/")[0] in TOP:
        bases = [loc]
    elif area in tree.areas:
        bases = [f"engine/src/{loc}", f"engine/include/wrc/{loc}"]
    else:
        return []
    stems = {os.path.splitext(b)[0] for b in bases if os.path.splitext(b)[1] in (".cpp", ".hpp", ".h", ".c")}
    return [f for f in tree.files
            if any(f == b or f.startswith(b + "/") for b in bases) or os.path.splitext(f)[0] in stems]


def check_placements(tree, page, text):
    """`name`, `name2` (`area/file.cpp`: `name3`, ...): each name is defined (a line that starts with code and
    names it: a definition or declaration, not a call inside a body) in the files of the location it is placed in."""
    ident, one = r"`([A-Za-z_]\w*(?:::\w+)*)`", r"`[A-Za-z_]\w*(?:::\w+)*`"
    for m in re.finditer(r"((?:%s(?:,\s*|\s+and\s+))*%s)\s+\(`([^`]+)`(?::((?:\s*%s,?)+))?" % (one, one, one), text):
        loc = m.group(2)
        if "/" not in loc or loc.split("/")[0] not in tree.areas + ["engine", "scripts", "plugins"]:
            continue
        files = location_files(tree, loc)
        if not files:
            continue  # the path check reports a location that does not exist
        names = re.findall(ident, m.group(1)) + re.findall(ident, m.group(3) or "")
        code = "\n".join(strip_comments(f, open(os.path.join(tree.root, f), encoding="utf-8",
                                                errors="replace").read()) for f in files)
        for name in names:
            last = name.split("::")[-1]
            if not re.search(r"(?m)^[A-Za-z#].*\b%s\b" % re.escape(last), code):
                report(page, line_of(text, m.start()), f"places `{name}` in `{loc}`, which does not define it")


def check_links(tree, page, text, in_docs):
    stripped = re.sub(r"(?<!`)(`+)(?!`)(.+?)(?<!`)\1(?!`)", lambda m: " " * len(m.group(0)), text, flags=re.S)
    for m in re.finditer(r"!?\[((?:[^\]]|\n)*?)\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)", stripped):
        target = m.group(2)
        line = line_of(text, m.start())
        if re.match(r"^[a-z]+:", target):
            continue
        path, _, anchor = target.partition("#")
        resolved = os.path.normpath(os.path.join(os.path.dirname(page), path)) if path else page
        rel = os.path.relpath(resolved, tree.root)
        if not os.path.exists(resolved):
            report(page, line, f"links to {target}: {rel} does not exist")
            continue
        if in_docs and not rel.startswith("docs/"):
            report(page, line, f"links to {target}, outside docs/: the site cannot follow it")
        if anchor:
            if not resolved.endswith(".md"):
                report(page, line, f"links to {target}: an anchor into a file that is not a page")
                continue
            for slug, who in ((slug_mkdocs, "mkdocs"), (slug_github, "GitHub")):
                if anchor not in anchors(resolved, slug):
                    report(page, line, f"links to {target}: no heading of {rel} has the anchor '{anchor}' on {who}")


def check_page(tree, page):
    text = without_fences(open(page, encoding="utf-8").read())
    for offset, span in code_spans(text):
        line = line_of(text, offset)
        check_paths(tree, page, line, span)
        check_name(tree, page, line, span)
    in_docs = os.path.relpath(page, tree.root).startswith("docs/")
    check_links(tree, page, text, in_docs)
    check_placements(tree, page, text)


# ---- README's own checks --------------------------------------------------------------------------------------

def table_after(path, heading):
    lines = open(path, encoding="utf-8").read().split("\n")
    start = next((i for i, l in enumerate(lines) if re.match(r"^#+\s+" + re.escape(heading) + r"\s*$", l)), None)
    if start is None:
        return None
    rows, i = [], start + 1
    while i < len(lines) and not lines[i].startswith("|"):
        i += 1
    while i < len(lines) and lines[i].startswith("|"):
        rows.append(lines[i])
        i += 1
    return rows


def read_or_report(root, rel):
    """The text of a file the checks need; a missing one is a problem, not a crash."""
    path = os.path.join(root, rel)
    if not os.path.exists(path):
        report(path, 1, f"{rel} is missing")
        return ""
    return open(path, encoding="utf-8").read()


def check_readme(root):
    readme = os.path.join(root, "README.md")
    lines = open(readme, encoding="utf-8").read().split("\n")
    count = len(lines) - (1 if lines[-1] == "" else 0)
    if count > 300:
        report(readme, count, f"README.md has {count} lines, more than 300: move the detail to docs/")
    commands = [l for l in lines if l.startswith(".ci/deps")]
    theirs = set(read_or_report(root, "docs/getting-started.md").split("\n"))
    for c in commands:
        if c not in theirs:
            report(readme, lines.index(c) + 1, f"set-up command not in docs/getting-started.md: {c}")
    if not commands:
        report(readme, 1, "README.md shows no set-up command (.ci/deps ...)")
    nav = set(re.findall(r"(?m)^\s*-\s*(?:[^:\n]+|\"[^\"]*\"):\s*([\w/.-]+\.md)\s*$",
                         read_or_report(root, "mkdocs.yml")))
    for page in sorted(glob.glob(os.path.join(root, "docs/**/*.md"), recursive=True)):
        rel = os.path.relpath(page, os.path.join(root, "docs"))
        if rel not in nav:
            report(os.path.join(root, "mkdocs.yml"), 1, f"docs/{rel} is not in the nav: the site does not reach it")
    paper_page = os.path.join(root, "docs/paper.md")
    ours = table_after(readme, "The paper in the code")
    paper = table_after(paper_page, "The paper in the code") if os.path.exists(paper_page) else None
    if not ours or ours != paper:
        report(readme, 1, "the paper-to-code table differs from the one of docs/paper.md (or is missing)")


def check_fs_reference(root):
    """Every function of wrc.fs (the luaL_Reg table of its binding) has its line in the Lua API page."""
    binding = read_or_report(root, "engine/src/lua/fs_binding.cpp")
    table = re.search(r"const luaL_Reg fns\[\] = \{(.*?)\{nullptr, nullptr\}", binding, flags=re.S)
    page = os.path.join(root, "docs/reference/lua-api.md")
    text = read_or_report(root, "docs/reference/lua-api.md")
    if not table:
        report(os.path.join(root, "engine/src/lua/fs_binding.cpp"), 1, "no luaL_Reg fns[] table of wrc.fs found")
        return
    for name in re.findall(r'\{"(\w+)",', table.group(1)):
        if f"`wrc.fs.{name}(" not in text:
            report(page, 1, f"wrc.fs.{name} (engine/src/lua/fs_binding.cpp) is not in the table of wrc.fs")


# ---- what the sources cite ------------------------------------------------------------------------------------

def clean_citation(title):
    title = re.sub(r"\n\s*(//|--|#|\*)?", " ", title)
    return re.sub(r"\s+", " ", title).strip()


def heading_starts(path, title):
    t = title.lower().rstrip(".")
    return any(h.lower().startswith(t) for _, h in headings(path))


def check_source(tree, path):
    try:
        text = open(path, encoding="utf-8").read()
    except (OSError, UnicodeDecodeError):
        return
    rel = os.path.relpath(path, tree.root)
    for m in re.finditer(r"README[\s,(/*#-]{0,12}\"([^\"]{1,160})\"", text):
        title = clean_citation(m.group(1))
        if not heading_starts(os.path.join(tree.root, "README.md"), title):
            report(rel, line_of(text, m.start()), f"cites README \"{title}\", which README.md has no heading for")
    for m in re.finditer(r"(docs/[\w/.-]+\.md)(?:\W{0,4}\"([^\"]{1,160})\")?", text):
        page = os.path.join(tree.root, m.group(1))
        line = line_of(text, m.start())
        if not os.path.exists(page):
            report(rel, line, f"cites {m.group(1)}, which does not exist")
        elif m.group(2) and not heading_starts(page, clean_citation(m.group(2))):
            report(rel, line, f"cites {m.group(1)} \"{clean_citation(m.group(2))}\", which has no such heading")
    for line, name in comment_file_names(rel, text):
        base = os.path.basename(name)
        area_path = "/" in name and name.split("/")[0] in tree.areas
        known = (any(f.endswith("/" + name) for f in tree.files) if area_path or name.startswith("wrc/")
                 else base in tree.basenames)
        if not known and base not in GENERATED:
            report(rel, line, f"a comment names {name}, which is not a file of the repository")
    design = os.path.join(tree.root, "docs/design.md")
    numbers = {re.match(r"(\d+)\.", h).group(1) for _, h in headings(design) if re.match(r"\d+\.", h)}
    for m in re.finditer(r"design\.md,?\s+sections?\s+(\d+)(?:(?:\s*-\s*|\s+and\s+|,\s*)(\d+))?", text):
        for n in filter(None, m.groups()):
            if n not in numbers:
                report(rel, line_of(text, m.start()), f"cites docs/design.md section {n}, which does not exist")


def comment_file_names(path, text):
    """(line, name) of the C++ file names (x.hpp, area/x.cpp) that the comments of a source file name."""
    if path.endswith((".cpp", ".hpp", ".h", ".c")):
        pattern = r"//[^\n]*|/\*.*?\*/"
    elif path.endswith(".lua"):
        pattern = r"--[^\n]*"
    else:
        pattern = r"(?m)(?:^|\s)#[^\n]*"
    for c in re.finditer(pattern, text, flags=re.S):
        for m in re.finditer(r"(?<![\w./<>-])((?:[\w-]+/)*[\w-]+\.(?:hpp|cpp))\b", c.group(0)):
            yield line_of(text, c.start() + m.start()), m.group(1)


def source_files(tree):
    for f in tree.files:
        top = f.split("/")[0]
        if top in ("engine", "scripts", "plugins", "examples", "tests", "cmake", ".ci", "profiles") \
                or f == "CMakeLists.txt":
            if f.startswith("tests/docs/"):
                continue  # this check and its self-test's planted references
            if f.endswith(SOURCE_EXT) or f.endswith("CMakeLists.txt") or top == ".ci":
                yield os.path.join(tree.root, f)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("root")
    parser.add_argument("--pages", nargs="*")
    parser.add_argument("--sources", nargs="*")
    args = parser.parse_args()
    root = os.path.abspath(args.root)
    tree = Tree(root)
    if args.pages is None:
        pages = [os.path.join(root, "README.md")] + sorted(glob.glob(os.path.join(root, "docs/**/*.md"),
                                                                     recursive=True))
        check_readme(root)
        check_fs_reference(root)
    else:
        pages = [os.path.abspath(p) for p in args.pages]
    for page in pages:
        check_page(tree, page)
    sources = source_files(tree) if args.sources is None else [os.path.abspath(s) for s in args.sources]
    for s in sources:
        check_source(tree, s)
    for p in problems:
        print(p.replace(root + "/", ""))
    if problems:
        print(f"{len(problems)} stale reference(s) in the documentation or the sources' citations of it")
        return 1
    print(f"{len(pages)} pages checked: every cited path, name, link and section exists")
    return 0


if __name__ == "__main__":
    sys.exit(main())

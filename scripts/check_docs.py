#!/usr/bin/env python3
"""Fails when README.md or docs/*.md point at something the repository does not have, or when any
document or tracked source file cites the private material the project was written from.

A reader only has the repository. So every relative Markdown link (inline or a reference
definition) must reach a file or folder in it, and its #anchor a heading of that file by GitHub's
slug rules; every path the text names under one of the repository's top-level folders (`src/...`,
`docs/...`, `config/...`, in backticks or not, in prose and in code blocks but not in program
output) and every Markdown file named alone (`world.md`) must exist; a citation such as
[Helbing 1995], an entry of docs/references.md, needs its link definition in the same file; and no
document may send the reader to material beside the repository (`../shared`, `shared/...`,
`specs/...`, DESIGN.md, the private specifications ari.md, ros4hri.md, algorithms.md and
wire_types.md) or cite the specification the project was written from as "seed 3.x", "seed
section ...", "the seed's ...", "(seed: ...)" ("seed" is the random seed only: cite D6.4 or
another entry of docs/references.md). Files a document shows how to create are declared in it,
`<!-- check_docs: new PATH... -->`.

The same citation rules hold for every tracked source, config, message, launch, URDF, build and
test file (SOURCE_SUFFIXES; `git ls-files`, or every file outside NOT_ROOTS without git), this
script and check_paths.py excepted, as they spell the patterns out. There is no exemption: public data sets are found
at run time (docs/data.md), never through a folder the build names.

Each problem is printed as `FILE:LINE: <target> does not exist` (or names the forbidden mention),
then a one-line count summary. Exit status 1 on any problem, 0 otherwise. Standard library only.

usage: /usr/bin/python3 scripts/check_docs.py [--repo DIR] [--self-test]
"""

import argparse
import fnmatch
import os
import re
import subprocess
import sys
import tempfile

# Folders a path in the text may start with. The existing top-level folders of the checked tree are
# added to these; one listed here that does not exist makes every path under it a missing one.
PATH_ROOTS = ("src", "include", "docs", "scripts", "launch", "config", "scenes", "worlds", "test",
              "bench", "cmake", "urdf", "msg", "srv", "action", "tools", "scenarios", ".ci")
# Generated or machine-local folders: named in commands, never in the repository.
NOT_ROOTS = {".git", "_build", "build", "devel"}

# Mentions that send the reader outside the repository, or cite the unpublished specification the
# project was written from instead of a public reference (docs/references.md).
FORBIDDEN = (
    (re.compile(r"\.\./shared"), "'../shared' (a folder outside the repository)"),
    (re.compile(r"(?<![\w./-])shared/"), "'shared/' (a folder outside the repository)"),
    (re.compile(r"(?<![\w.-])specs/"), "'specs/' (a specification outside the repository)"),
    (re.compile(r"(?<![\w./-])(?:DESIGN|ari|ros4hri|algorithms|wire_types)\.md\b"),
     "a private specification (cite docs/references.md instead)"),
    (re.compile(r"\bspecs \d"), "'specs N' (cite docs/references.md instead)"),
    (re.compile(r"\bseed \d+\.\d", re.IGNORECASE), "'seed N.N' (cite docs/references.md instead)"),
    (re.compile(r"\bseed (?:§|(?:section|sections|document|eq|eqs|equations?|fig|figure|table|"
                r"module|symbol)\b)", re.IGNORECASE),
     "'seed section' (cite docs/references.md instead)"),
    (re.compile(r"\bthe seed's\b", re.IGNORECASE),
     "'the seed's' (cite docs/references.md instead)"),
    (re.compile(r"\(seed:", re.IGNORECASE), "'(seed: ...)' (cite docs/references.md instead)"),
)

# The files whose comments and text the citation rules cover besides the documents.
SOURCE_SUFFIXES = (".cpp", ".hpp", ".h", ".py", ".yaml", ".msg", ".srv", ".action", ".launch",
                   ".test", ".cmake", ".txt", ".sh", ".xml", ".urdf", ".rviz")
SOURCE_NAMES = ("CMakeLists.txt", ".ci/run")
THIS_SCRIPT = "scripts/check_docs.py"
# The checks that spell the forbidden mentions out as patterns and in their self-tests.
PATTERN_SCRIPTS = (THIS_SCRIPT, "scripts/check_paths.py")

FENCE = re.compile(r"^\s*(```|~~~)\s*([\w+-]*)")
# Fenced blocks without a language (or marked text) hold program output, which may quote files of
# an example (`scenes/bad.yaml: humans[0]: ...`); paths are checked in prose and in code.
OUTPUT_FENCES = ("", "text", "json")
HEADING = re.compile(r"^\s{0,3}(#{1,6})\s+(.*?)\s*#*\s*$")
HTML_ANCHOR = re.compile(r"""<a\s+(?:name|id)\s*=\s*["']([^"']+)["']""", re.IGNORECASE)
# [text](target) and ![alt](target); the target ends at whitespace (a title may follow) or ')'.
INLINE_LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+[\"'][^)]*)?\)")
# [label]: target, at the start of a line.
REFERENCE_DEFINITION = re.compile(r"^\s{0,3}\[([^\]]+)\]:\s*<?(\S+?)>?(?:\s+.*)?$")
# [label] used as a shortcut reference link (not [text](...), [text][ref] or a definition).
SHORTCUT_REFERENCE = re.compile(r"(?<![\]!\\])\[([^\[\]]+)\](?![(\[:])")
# A Markdown file named without a folder (`perception_gcff.md`); upper-case stems of at most four
# letters are placeholders of usage lines (`--report R.md`, `FILE.md`).
BARE_MARKDOWN = re.compile(r"(?<![\w./~$<>{}*-])([\w-]+\.md)\b")
PLACEHOLDER = re.compile(r"^[A-Z]{1,4}\.md$")
# Files a document shows how to create (docs/extending.md's examples), declared in the document:
# <!-- check_docs: new src/x.cpp include/y.hpp -->. Only those exact paths are exempt, in that file.
NEW_FILES = re.compile(r"<!--\s*check_docs:\s*new\s+(.*?)-->")
CODE_SPAN = re.compile(r"(`+)(.+?)\1")
SCHEME = re.compile(r"^[a-zA-Z][a-zA-Z0-9+.-]*:")


def github_slug(text):
    """The anchor GitHub gives a heading: its rendered text lower-cased, punctuation dropped,
    spaces turned into hyphens (not collapsed)."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", text)  # a link counts by its text
    text = re.sub(r"<[^>]+>", "", text)  # inline HTML
    text = text.replace("`", "").replace("*", "")
    text = re.sub(r"[^\w\- ]", "", text.lower())
    return text.replace(" ", "-")


class Document:
    """One Markdown file: its lines, which of them are inside fenced code, its anchors."""

    def __init__(self, path):
        self.path = path
        with open(path, encoding="utf-8") as f:
            self.lines = f.read().split("\n")
        self.in_fence = []  # per line: None in prose, else the fence's language ("" for none)
        fence = language = None
        for line in self.lines:
            match = FENCE.match(line)
            if fence is None and match:
                fence, language = match.group(1), match.group(2).lower()
                self.in_fence.append(language)
            elif fence is not None:
                self.in_fence.append(language)
                if match and match.group(1) == fence:
                    fence = None
            else:
                self.in_fence.append(None)
        self.new_files = set()
        for line in self.lines:
            for declared in NEW_FILES.findall(line):
                self.new_files.update(declared.split())
        self.anchors = set()
        seen = {}
        for line, fenced in zip(self.lines, self.in_fence):
            if fenced is not None:
                continue
            heading = HEADING.match(line)
            if heading:
                slug = github_slug(heading.group(2))
                count = seen.get(slug, 0)
                seen[slug] = count + 1
                self.anchors.add(slug if count == 0 else "%s-%d" % (slug, count))
            for anchor in HTML_ANCHOR.findall(line):
                self.anchors.add(anchor)


class Checker:
    def __init__(self, repo):
        self.repo = os.path.realpath(repo)
        self.documents = {}
        self.problems = []
        self.links = 0
        self.anchors = 0
        self.paths = 0
        roots = set(PATH_ROOTS)
        for name in os.listdir(self.repo):
            if os.path.isdir(os.path.join(self.repo, name)) and name not in NOT_ROOTS:
                roots.add(name)
        # The citation keys: the entries (### headings) of docs/references.md.
        self.citations = set()
        references = os.path.join(self.repo, "docs", "references.md")
        if os.path.isfile(references):
            doc = self.document(references)
            for line, fenced in zip(doc.lines, doc.in_fence):
                heading = HEADING.match(line)
                if fenced is None and heading and len(heading.group(1)) == 3:
                    self.citations.add(heading.group(2).lower())
        names = "|".join(re.escape(r) for r in sorted(roots, key=len, reverse=True))
        # A path starts where no path character precedes it, so `src/tools/x` is not `tools/x`.
        self.path_token = re.compile(r"(?<![\w./~$<>{}*-])((?:%s)/[\w./*?<>{},+-]*)" % names)

    def document(self, path):
        path = os.path.realpath(path)
        if path not in self.documents:
            self.documents[path] = Document(path)
        return self.documents[path]

    def report(self, doc, number, message):
        problem = "%s:%d: %s" % (os.path.relpath(doc.path, self.repo), number, message)
        if problem not in self.problems:  # a link's text often names its target too
            self.problems.append(problem)

    def inside(self, path):
        path = os.path.realpath(path)
        return path == self.repo or path.startswith(self.repo + os.sep)

    # ---- links ----------------------------------------------------------------------------------
    def check_link(self, doc, number, target):
        if SCHEME.match(target) or target.startswith("//"):
            return  # a web address: not checked offline
        self.links += 1
        path_part, _, anchor = target.partition("#")
        if path_part:
            resolved = os.path.normpath(os.path.join(os.path.dirname(doc.path), path_part))
            if not self.inside(resolved) or not os.path.exists(resolved):
                self.report(doc, number, "%s does not exist" % target)
                return
        else:
            resolved = doc.path
        if anchor:
            self.anchors += 1
            if not resolved.endswith(".md") or not os.path.isfile(resolved):
                return  # anchors of other files (source lines, ...) are not checked
            if anchor.lower() not in self.document(resolved).anchors:
                self.report(doc, number, "%s does not exist" % target)

    # ---- paths named in the text ----------------------------------------------------------------
    def candidates(self, token):
        """The patterns a named path stands for: {a,b} expanded, <placeholder> as a wildcard."""
        token = token.rstrip(".,;:")
        while token.endswith("..."):
            token = token[:-3].rstrip("/")
        token = re.sub(r"<[^<>/]*>", "*", token)
        patterns = [token]
        while any("{" in p for p in patterns):
            expanded = []
            for p in patterns:
                match = re.search(r"\{([^{}]*)\}", p)
                if not match:
                    expanded.append(p)
                    continue
                for part in match.group(1).split(","):
                    expanded.append(p[:match.start()] + part + p[match.end():])
            patterns = expanded
        return token, patterns

    def exists(self, pattern):
        pattern = pattern.rstrip("/")
        if not any(c in pattern for c in "*?["):
            return os.path.exists(os.path.join(self.repo, pattern))
        parts = pattern.split("/")
        current = [self.repo]
        for i, part in enumerate(parts):
            last = i == len(parts) - 1
            following = []
            for folder in current:
                if part == "**":
                    following.extend(root for root, _, _ in os.walk(folder))
                    continue
                try:
                    names = os.listdir(folder)
                except OSError:
                    continue
                for name in fnmatch.filter(names, part):
                    full = os.path.join(folder, name)
                    if last or os.path.isdir(full):
                        following.append(full)
            current = following
        return bool(current)

    def check_paths(self, doc, number, text):
        for match in self.path_token.finditer(text):
            token, patterns = self.candidates(match.group(1))
            self.paths += 1
            if token in doc.new_files:
                continue
            if not all(self.exists(p) for p in patterns):
                self.report(doc, number, "%s does not exist" % token)
        for name in BARE_MARKDOWN.findall(text):
            if PLACEHOLDER.match(name):
                continue
            self.paths += 1
            folders = (os.path.dirname(doc.path), self.repo, os.path.join(self.repo, "docs"))
            if not any(os.path.isfile(os.path.join(folder, name)) for folder in folders):
                self.report(doc, number, "%s does not exist" % name)

    # ---- a whole document -----------------------------------------------------------------------
    def check(self, path):
        doc = self.document(path)
        defined = set()
        for line, fenced in zip(doc.lines, doc.in_fence):
            definition = REFERENCE_DEFINITION.match(line)
            if fenced is None and definition:
                defined.add(definition.group(1).lower())
        for index, line in enumerate(doc.lines):
            number = index + 1
            for pattern, what in FORBIDDEN:
                if pattern.search(line):
                    self.report(doc, number, "mentions %s" % what)
            fence = doc.in_fence[index]
            if fence not in OUTPUT_FENCES and not NEW_FILES.search(line):
                self.check_paths(doc, number, line)
            if fence is not None:
                continue
            # Links, outside code spans (a link written in backticks is text, not a link).
            prose = CODE_SPAN.sub(lambda m: " " * len(m.group(0)), line)
            definition = REFERENCE_DEFINITION.match(prose)
            if definition:
                self.check_link(doc, number, definition.group(2))
                continue
            for target in INLINE_LINK.findall(prose):
                self.check_link(doc, number, target)
            # A citation such as [Helbing 1995] needs its link definition in the same file.
            for label in SHORTCUT_REFERENCE.findall(INLINE_LINK.sub("", prose)):
                if label.lower() in self.citations and label.lower() not in defined:
                    self.report(doc, number, "[%s] has no link definition (add `[%s]: "
                                "references.md#%s` at the end of the file)"
                                % (label, label, github_slug(label)))

    # ---- source files ---------------------------------------------------------------------------
    def source_files(self):
        """The repository's files the citation rules cover, relative to it: the tracked ones when
        it is a git work tree, else every file outside NOT_ROOTS."""
        try:
            listed = subprocess.run(["git", "-C", self.repo, "ls-files", "-z"], check=True,
                                    stdout=subprocess.PIPE, stderr=subprocess.DEVNULL).stdout
            names = [n for n in listed.decode("utf-8").split("\0") if n]
        except (OSError, subprocess.CalledProcessError):
            names = []
            for root, folders, files in os.walk(self.repo):
                folders[:] = sorted(f for f in folders if f not in NOT_ROOTS)
                names += [os.path.relpath(os.path.join(root, f), self.repo) for f in files]
        return sorted(n for n in names
                      if n not in PATTERN_SCRIPTS and
                      (n.endswith(SOURCE_SUFFIXES) or n in SOURCE_NAMES))

    def check_source(self, name):
        try:
            with open(os.path.join(self.repo, name), encoding="utf-8") as f:
                lines = f.read().split("\n")
        except (OSError, UnicodeDecodeError):
            return  # deleted but still listed, or not text
        for number, line in enumerate(lines, 1):
            for pattern, what in FORBIDDEN:
                if pattern.search(line):
                    problem = "%s:%d: mentions %s" % (name, number, what)
                    if problem not in self.problems:
                        self.problems.append(problem)

    def run(self):
        files = [os.path.join(self.repo, "README.md")]
        docs = os.path.join(self.repo, "docs")
        if os.path.isdir(docs):
            files += sorted(os.path.join(docs, n) for n in os.listdir(docs) if n.endswith(".md"))
        files = [f for f in files if os.path.isfile(f)]
        for path in files:
            self.check(path)
        sources = self.source_files()
        for name in sources:
            self.check_source(name)
        return files, sources


def check_repository(repo, quiet=False):
    checker = Checker(repo)
    files, sources = checker.run()
    if not quiet:
        for problem in checker.problems:
            print(problem)
        print("check_docs: %d files, %d relative links (%d with anchors), %d repository paths, "
              "%d source files: %d problems" % (len(files), checker.links, checker.anchors,
                                                checker.paths, len(sources),
                                                len(checker.problems)))
    return checker


def write(root, relative, text):
    path = os.path.join(root, relative)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def self_test():
    """A small tree with one broken link, one broken anchor, one missing path and one `../shared`
    mention in the documents, and private citations in a document, a source file, a message, a
    CMake file (a data folder beside the checkout) and a test, beside correct ones (the random
    seed, a public citation, this script's own patterns, a build folder): each problem must be
    reported, and nothing else."""
    with tempfile.TemporaryDirectory() as root:
        write(root, "src/core/rng.cpp", "\n".join([
            "// Walkers (D6.4 §3.3.1); Rng rng(seed); run --seed 3 (seed 7); \"seed: 1\"",
            "// Gaze as in seed 3.3.2.",
            "/// Controllers (specs/ari.md §2).",
            "",
        ]))
        write(root, "msg/State.msg", "# Colours as in the seed's GUI\n"
              "string act  # (seed: previous_speech_act)\n")
        write(root, "cmake/data.cmake",
              'set(ARI_MPGT_DIR "${CMAKE_CURRENT_SOURCE_DIR}/../shared/mpgt" CACHE PATH "MPGT")\n'
              "# CI clones shared/ beside the checkout\n")
        write(root, "test/test_groups.py", "# the protocol of algorithms.md 1.4\n")
        write(root, THIS_SCRIPT, "PATTERN = 'shared/ and seed 3.3'\n")
        write(root, "_build/generated.cpp", "// seed section 3\n")
        write(root, "docs/guide.md",
              "# Guide\n\n## Real heading, with `code`\n\nSee [the README](../README.md).\n"
              "As in the seed's figure 3.5.\n")
        write(root, "docs/references.md", "# References\n\n### Helbing 1995\n\nA paper.\n")
        write(root, "README.md", "\n".join([
            "# Project",
            "[fine](docs/guide.md#real-heading-with-code) and `src/core/rng.cpp`, src/core/.",
            "[broken link](docs/missing.md)",
            "[broken anchor](docs/guide.md#no-such-heading)",
            "The seeded generator lives in `src/core/random.cpp`.",
            "Read ../shared/DESIGN.md first.",
            "Social forces [Helbing 1995]; guide.md; docs/*.md; `--report R.md`.",
            "```sh",
            "echo '[not a link](#nowhere)'",
            "```",
            "",
            "[Helbing 1995]: docs/references.md#helbing-1995",
            "",
        ]))
        checker = check_repository(root, quiet=True)
    expected = [
        "README.md:3: docs/missing.md does not exist",
        "README.md:4: docs/guide.md#no-such-heading does not exist",
        "README.md:5: src/core/random.cpp does not exist",
        "README.md:6: mentions '../shared' (a folder outside the repository)",
        "docs/guide.md:6: mentions 'the seed's' (cite docs/references.md instead)",
        "src/core/rng.cpp:2: mentions 'seed N.N' (cite docs/references.md instead)",
        "src/core/rng.cpp:3: mentions 'specs/' (a specification outside the repository)",
        "msg/State.msg:1: mentions 'the seed's' (cite docs/references.md instead)",
        "msg/State.msg:2: mentions '(seed: ...)' (cite docs/references.md instead)",
        "cmake/data.cmake:1: mentions '../shared' (a folder outside the repository)",
        "cmake/data.cmake:2: mentions 'shared/' (a folder outside the repository)",
        "test/test_groups.py:1: mentions a private specification (cite docs/references.md "
        "instead)",
    ]
    ok = True
    for line in expected:
        found = line in checker.problems
        print("self-test: %s %s" % ("caught" if found else "MISSED", line))
        ok = ok and found
    unexpected = [p for p in checker.problems if p not in expected]
    for line in unexpected:
        print("self-test: UNEXPECTED %s" % line)
    ok = ok and not unexpected
    print("check_docs self-test: %s" % ("passed" if ok else "FAILED"))
    return ok


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repo", default=os.path.dirname(os.path.dirname(os.path.abspath(
        __file__))), help="repository root (default: this script's repository)")
    parser.add_argument("--self-test", action="store_true",
                        help="check that a broken link, anchor, path, ../shared mention and "
                             "private citations (documents and source files) in a temporary tree "
                             "are each reported, instead of checking the repository")
    args = parser.parse_args()
    if args.self_test:
        return 0 if self_test() else 1
    return 1 if check_repository(args.repo).problems else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Checks the relative links of the Markdown files: every file a link names is there, and every
anchor (#frag) into a Markdown file names one of its headings.

  scripts/check-links.py [ROOT]

ROOT is the repository (default: this script's). Its Markdown files are the *.md files git
tracks under ROOT; when git tracks nothing there (a handout folder is no checkout), every *.md
file under ROOT, build/ folders and hidden folders left out.

What is a link: an inline link [text](target) or image ![alt](target), a reference definition
[label]: target, an HTML <a href="target"> or <img src="target">; not in a fenced code block, an
inline code span or an HTML comment. A target with a scheme (http:, https:, mailto:, ...) or
//host is skipped. The rest, as GitHub reads it:
  - the file part (percent-decoded, without ?query) must exist, relative to the Markdown file
    (from ROOT when it starts with /); a directory is fine;
  - an anchor #frag into a .md file must be one of its headings' GitHub slugs (lower case,
    punctuation but '-' and '_' removed, each space a '-'; the text of `code`, of links and of
    emphasis kept; the second heading of a slug gets -1, the third -2, ...) or the id or name
    of an HTML tag (<a id="frag">, <a name="frag">); a bare #frag is into the same file. An
    anchor into another kind of file or a directory is not checked.

Prints one line per problem, then a summary line:
  FILE:LINE: missing file TARGET           TARGET as the link writes it, without #frag
  FILE:LINE: no heading for #FRAG in MD    MD the Markdown file the link points into
FILE and MD are relative to ROOT.
"""
from __future__ import annotations

import argparse
import bisect
import html
import os
import re
import subprocess
import sys
import unicodedata
from pathlib import Path
from urllib.parse import unquote

# The Python tools' shared module, grading/tooling.py.
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "grading"))
from tooling import EXIT_INTERRUPTED, Written, run_command_line  # noqa: E402

PROGRAM = "check-links"
EXIT_OK, EXIT_BROKEN, EXIT_USAGE = 0, 1, 2

FENCE_OPEN = re.compile(r"^[ \t]*(`{3,}|~{3,})(.*)$")
ATX_HEADING = re.compile(r"^ {0,3}#{1,6}(?:[ \t]+(.*?))?[ \t]*$")
SETEXT_UNDERLINE = re.compile(r"^ {0,3}(?:=+|-+)[ \t]*$")
NOT_A_PARAGRAPH = re.compile(r"^\s*(?:$|#|\||>|<|[-+*][ \t]|\d+[.)][ \t]|`{3}|~{3})")
COMMENT = re.compile(r"<!--.*?-->", re.S)
BLOCK = re.compile(r"(?:^[ \t]*\S.*(?:\n|\Z))+", re.M)  # lines up to a blank one
BACKTICKS = re.compile(r"`+")
ESCAPED = re.compile(r"\\[!-/:-@\[-`{-~]")  # a backslash escape of an ASCII punctuation
LINK_OPEN = re.compile(r"\]\(")
REFERENCE = re.compile(r"^ {0,3}\[([^\]^][^\]]*)\]:[ \t]*(?:<([^>\n]*)>|(\S+))", re.M)
TAG = re.compile(r"<([A-Za-z][A-Za-z0-9-]*)(\s[^<>]*?)?/?>")
ATTRIBUTE = re.compile(r"""\s([A-Za-z_:][-A-Za-z0-9_:.]*)\s*=\s*"""
                       r"""(?:"([^"]*)"|'([^']*)'|([^\s"'=<>`]+))""")
SCHEME = re.compile(r"^(?:[A-Za-z][A-Za-z0-9+.-]*:|//)")
EMPHASIS_UNDERSCORES = re.compile(r"(?<![^\W_])_+|_+(?![^\W_])")


def blank(chars: list[str], start: int, end: int, fill: str = " ") -> None:
    """chars[start:end] overwritten with fill, its newlines kept (the line numbers stay)."""
    for k in range(start, end):
        if chars[k] != "\n":
            chars[k] = fill


class Markdown:
    """One Markdown file read: its links (line, target, whether from HTML) and its anchors."""

    def __init__(self, text: str) -> None:
        self.links: list[tuple[int, str, bool]] = []
        self.anchors: set[str] = set()
        lines = text.split("\n")
        self._fences_blanked(lines)
        chars = list("\n".join(lines))
        for m in COMMENT.finditer("".join(chars)):
            blank(chars, m.start(), m.end())
        prose = "".join(chars)
        self._headings(prose.split("\n"))
        blocks = [(m.start(), m.end()) for m in BLOCK.finditer(prose)]
        for start, end in blocks:
            self._code_spans_blanked(chars, start, end)
        for m in ESCAPED.finditer(prose):  # never a bracket, a parenthesis or a tag's start
            if chars[m.start()] == "\\":
                blank(chars, m.start(), m.end(), "\x01")
        clean = "".join(chars)
        line_starts = [0] + [m.end() for m in re.finditer("\n", clean)]
        self._line_of = lambda offset: bisect.bisect_right(line_starts, offset)
        for start, end in blocks:
            self._inline_links(clean, prose, start, end)
        for m in REFERENCE.finditer(clean):
            target = prose[m.start(2):m.end(2)] if m.group(2) is not None else \
                prose[m.start(3):m.end(3)]
            self.links.append((self._line_of(m.start()), target, False))
        self._html(clean, prose)
        self.links.sort(key=lambda link: link[0])  # in line order, whatever their kind

    @staticmethod
    def _fences_blanked(lines: list[str]) -> None:
        """The lines of fenced code blocks, their fences included, made empty."""
        fence = ""
        for k, line in enumerate(lines):
            if fence:
                stripped = line.strip()
                if stripped.startswith(fence) and stripped.strip(fence[0]) == "":
                    fence = ""
                lines[k] = ""
            elif (m := FENCE_OPEN.match(line)) and not (m.group(1)[0] == "`" and "`" in m.group(2)):
                fence = m.group(1)
                lines[k] = ""

    def _headings(self, lines: list[str]) -> None:
        """The GitHub slugs of the ATX and setext headings: the second heading of a slug gets -1,
        the third -2, as github-slugger numbers them."""
        counts: dict[str, int] = {}
        for k, line in enumerate(lines):
            if m := ATX_HEADING.match(line):
                text = re.sub(r"(?:^|[ \t]+)#+$", "", m.group(1) or "")
            elif k and SETEXT_UNDERLINE.match(line) and not NOT_A_PARAGRAPH.match(lines[k - 1]):
                text = lines[k - 1]
            else:
                continue
            slug = base = github_slug(text)
            while slug in counts:
                counts[base] += 1
                slug = f"{base}-{counts[base]}"
            counts[slug] = 0
            self.anchors.add(slug)

    @staticmethod
    def _code_spans_blanked(chars: list[str], start: int, end: int) -> None:
        """The code spans of one block (chars[start:end]) blanked: a run of backticks up to the
        next run of as many; a run without one is text."""
        runs = [(m.start() + start, m.end() + start)
                for m in BACKTICKS.finditer("".join(chars[start:end]))]
        k = 0
        while k < len(runs):
            length = runs[k][1] - runs[k][0]
            close = next((j for j in range(k + 1, len(runs))
                          if runs[j][1] - runs[j][0] == length), None)
            if close is None:
                k += 1
                continue
            blank(chars, runs[k][0], runs[close][1])
            k = close + 1

    def _inline_links(self, clean: str, prose: str, start: int, end: int) -> None:
        """The [text](target) and ![alt](target) of one block (clean[start:end]): a "](" with
        its "[" before it, then a destination (<...>, or up to a space or an unbalanced
        parenthesis), an optional title and ")"."""
        for m in LINK_OPEN.finditer(clean, start, end):
            bracket = opening(clean, start, m.start())
            if bracket < 0:
                continue
            k = m.end()
            while k < end and clean[k] in " \t":
                k += 1
            if k < end and clean[k] == "\n":
                k += 1
                while k < end and clean[k] in " \t":
                    k += 1
            if k < end and clean[k] == "<":
                close = clean.find(">", k, end)
                if close < 0 or "\n" in clean[k:close]:
                    continue
                first, stop, after = k + 1, close, close + 1
            else:
                depth, first = 0, k
                while k < end and not clean[k].isspace():
                    if clean[k] == "(":
                        depth += 1
                    elif clean[k] == ")":
                        if depth == 0:
                            break
                        depth -= 1
                    k += 1
                stop = after = k
            rest = clean[after:end].lstrip()
            if rest[:1] in ('"', "'", "("):  # a title
                closing = ")" if rest[0] == "(" else rest[0]
                title_end = rest.find(closing, 1)
                rest = rest[title_end + 1:].lstrip() if title_end > 0 else ""
            if rest[:1] == ")":
                self.links.append((self._line_of(bracket), prose[first:stop], False))

    def _html(self, clean: str, prose: str) -> None:
        """<a href> and <img src> as links; the id of any tag and the name of an <a> as
        anchors."""
        for tag in TAG.finditer(clean):
            name = tag.group(1).lower()
            if tag.group(2) is None:
                continue
            for a in ATTRIBUTE.finditer(clean, tag.start(2), tag.end(2)):
                attribute = a.group(1).lower()
                group = next(g for g in (2, 3, 4) if a.group(g) is not None)
                value = html.unescape(prose[a.start(group):a.end(group)])
                if attribute == "id" or (attribute == "name" and name == "a"):
                    self.anchors.add(value)
                elif (name, attribute) in (("a", "href"), ("img", "src")):
                    self.links.append((self._line_of(a.start(1)), value, True))


def opening(clean: str, start: int, close: int) -> int:
    """Where the "[" of the "]" at close is, from start on; -1 when it has none."""
    depth = 0
    for k in range(close - 1, start - 1, -1):
        if clean[k] == "]":
            depth += 1
        elif clean[k] == "[":
            if depth == 0:
                return k
            depth -= 1
    return -1


def github_slug(heading: str) -> str:
    """The anchor GitHub gives a heading: its text as shown (code spans' text, a link's or an
    image's text, without tags or emphasis), lower case, each character that is not a letter, a
    digit, a mark, '_', '-' or a space removed, each space a '-'."""
    parts = re.split(r"(`+)(.+?)(?<!`)\1(?!`)", heading)
    shown = []
    for k in range(0, len(parts), 3):
        text = parts[k]
        text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", text)
        text = re.sub(r"<[^>]*>", "", text)
        text = EMPHASIS_UNDERSCORES.sub("", text)
        text = re.sub(r"\\([!-/:-@\[-`{-~])", r"\1", text)
        shown.append(html.unescape(text))
        if k + 2 < len(parts):
            shown.append(parts[k + 2])
    return "".join(c for c in "".join(shown).strip().lower()
                   if unicodedata.category(c)[0] in "LMN" or c in "_- ").replace(" ", "-")


def markdown_files(root: Path) -> list[Path]:
    """The *.md files git tracks under root; when it tracks nothing there (no checkout), every
    *.md file under it, build/ and hidden folders left out."""
    try:
        run = subprocess.run(["git", "-C", str(root), "ls-files", "-z", "--cached"],
                             capture_output=True, text=True, check=False)
        tracked = [name for name in run.stdout.split("\0") if name] if run.returncode == 0 else []
    except OSError:  # no git
        tracked = []
    if tracked:
        return sorted(root / name for name in tracked
                      if name.endswith(".md") and (root / name).is_file())
    found = []
    for folder, folders, files in os.walk(root):
        folders[:] = sorted(f for f in folders if f != "build" and not f.startswith("."))
        found += [Path(folder) / f for f in files if f.endswith(".md")]
    return sorted(found)


class Checker:
    def __init__(self, root: Path) -> None:
        self.root = root
        self.read: dict[Path, Markdown] = {}
        self.checked = 0  # the relative links checked so far

    def markdown(self, path: Path) -> Markdown:
        if path not in self.read:
            self.read[path] = Markdown(path.read_text(encoding="utf-8", errors="replace"))
        return self.read[path]

    def where(self, path: Path) -> str:
        return os.path.relpath(path, self.root)

    def problems(self, path: Path) -> list[str]:
        """The lines of the links of path that do not resolve."""
        found = []
        for line, written, from_html in self.markdown(path).links:
            target = written if from_html else html.unescape(ESCAPED.sub(
                lambda m: m.group(0)[1], written))
            if not target or SCHEME.match(target):
                continue
            self.checked += 1
            file_part, _, fragment = target.partition("#")
            file_part = file_part.partition("?")[0]
            if file_part:
                base = self.root if file_part.startswith("/") else path.parent
                resolved = Path(os.path.normpath(base / unquote(file_part).lstrip("/")))
                if not resolved.exists():
                    found.append(f"{self.where(path)}:{line}: missing file "
                                 f"{written.partition('#')[0]}")
                    continue
            else:
                resolved = path
            if (fragment and resolved.suffix.lower() == ".md" and resolved.is_file() and
                    unquote(fragment) not in self.markdown(resolved).anchors):
                found.append(f"{self.where(path)}:{line}: no heading for #{fragment} in "
                             f"{self.where(resolved)}")
        return found


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(
        prog="scripts/check-links.py",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        description="Checks that every relative link of the Markdown files resolves: the\n"
                    "file it names is there, and an anchor (#frag) into a Markdown file names\n"
                    "one of its headings (as GitHub makes their anchors) or an <a id>/<a name>.\n"
                    "Links with a scheme (http:, https:, mailto:, ...) are not checked, nor\n"
                    "links in fenced code blocks, code spans and HTML comments.",
        epilog="Prints one line per problem, then a summary line:\n"
               "  FILE:LINE: missing file TARGET         (TARGET as written, without #frag)\n"
               "  FILE:LINE: no heading for #FRAG in MD  (MD: the Markdown file linked to)\n"
               "FILE and MD relative to ROOT.\n\n"
               "Exit codes: 0 every link resolves; 1 some do not; 2 bad usage (ROOT not a\n"
               "directory); 130 interrupted (Ctrl-C); 141 the reader of the output went away\n"
               "(| head).")
    parser.add_argument("root", nargs="?", type=Path, metavar="ROOT",
                        default=Path(__file__).resolve().parent.parent,
                        help="the folder whose Markdown files are checked: the *.md files git "
                             "tracks under it, or, when it tracks none there (a handout), every "
                             "*.md file under it but in build/ and hidden folders (default: "
                             "this script's repository)")
    try:
        args = parser.parse_args(argv)
    except SystemExit as e:
        return EXIT_OK if e.code == 0 else EXIT_USAGE
    if not args.root.is_dir():
        print(f"{PROGRAM}: error: ROOT '{args.root}' is not a directory", file=sys.stderr)
        return EXIT_USAGE
    root = args.root.resolve()
    try:
        checker = Checker(root)
        files = markdown_files(root)
        problems, broken = 0, 0
        for path in files:
            found = checker.problems(path)
            for line in found:
                print(line)
            problems += len(found)
            broken += bool(found)
        if problems:
            print(f"{PROGRAM}: {problems} of {checker.checked} relative link(s) broken, in "
                  f"{broken} of {len(files)} Markdown file(s)")
            return EXIT_BROKEN
        print(f"{PROGRAM}: {checker.checked} relative link(s) in {len(files)} Markdown file(s): "
              "all resolve")
        return EXIT_OK
    except KeyboardInterrupt:
        print(Written().interrupted(PROGRAM, None), file=sys.stderr)
        return EXIT_INTERRUPTED


if __name__ == "__main__":
    sys.exit(run_command_line(main, sys.argv[1:]))

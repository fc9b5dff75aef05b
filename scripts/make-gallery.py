#!/usr/bin/env python3
"""Writes the gallery, docs/index.html: one static page of the course.

  scripts/make-gallery.py [--root DIR] [--bench FILE] [-o FILE]

The page shows, from what the repository holds (nothing is rendered here):
  - the stage map: every stage folder (stageNN_*, miniN_*) in course order, with the first
    paragraph of its README and the images of docs/images/ its README links;
  - the galaxy with and without diffused glass (docs/images/galaxy.png and
    docs/images/galaxy-clear.png);
  - every other image of docs/images/ (a scene's reference image is `rt render NAME
    --width 500`, see scripts/render-docs-images.sh);
  - the timing across stages, from the JSON that `rt bench --json` writes, read from
    docs/bench.json (or --bench FILE): two charts drawn with matplotlib (inline SVG), the
    reference report's rows on a log scale with the report's times beside ours, and the
    stages' tracers as rays per second; then a table.
Whatever is missing (a README, a linked image, the galaxy pair, the timing) is left out of the
page, said so on it, and listed on stderr as "make-gallery: missing: ...". The exit code is 0
then too; 2 for bad usage (a --bench FILE that is not there, an output the page cannot be written
to, checked before any work) or a timing file that does not follow the schema below; 1 when
writing the page fails all the same; 130 when interrupted (Ctrl-C): one line on stderr says so
and whether the page was written ("interrupted after writing PAGE" once it is whole, else
"interrupted; nothing written to PAGE", an earlier page left as it was); 141 when the reader of
its output went away (a pipe closed early, `scripts/make-gallery.py | head -1`): it stops there,
quietly, as a program that SIGPIPE ends. The page is written whole or not at all (a folder made
for it is removed again when it is not).

The timing file, as `rt bench --json` writes it:
  {"scene": "...", "width": W, "height": H,
   "rows": [{"name": "...", "tracer": "...", "accel": "none|cbr|bvh|bvh4|grid|embree",
             "threads": N, "seconds": S, "primary": P, "secondary": Q, "shadow": R,
             "raysPerSecond": X, "nodesPerRay": Y, "speedup": Z,
             "referenceSeconds": null or a number, "pixelsDiffering": null or a count,
             "note": "..."}]}
  (the reference report's time for the row; the pixels whose colour differs from the first
  row's image). A row that was not rendered (Embree 3 in a build without Embree) has null for
  its figures, S to Z, and a note saying why: it is left out of the charts and shown in the
  table with its note; a row whose structure does not count nodes (Embree) has null for Y.
  pixelsDiffering and note may be missing (files written before they were).

--root is the repository (default: this script's); the page's links, images and style sheet
(docs/gallery.css of this script's repository) are relative to the output file, so the page works opened as a file or served over HTTP from the repository.
python3 and matplotlib come with scripts/deps.sh python3 python3-matplotlib. Run by another
python3 that lacks matplotlib (a pyenv one, first on PATH), it says so, and when Debian's
/usr/bin/python3 has it, how to run the script with that one.
"""
from __future__ import annotations

import argparse
import html
import json
import math
import os
import re
import shlex
import struct
import subprocess
import sys
from decimal import ROUND_HALF_UP, Decimal
from pathlib import Path

# The Python tools' shared module, grading/tooling.py.
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "grading"))
from tooling import (EXIT_INTERRUPTED, Written, output_problem, run_command_line,  # noqa: E402
                     write_whole)

PROGRAM = "make-gallery"
STYLESHEET = Path(__file__).resolve().parent.parent / "docs" / "gallery.css"
STAGE_FOLDER = re.compile(r"^(stage|mini)(\d+)_[A-Za-z0-9_]+$")
# A link or an <img> of a stage README (one folder down); a path in running text or in a command
# (`rt compare NAME.png docs/images/NAME.png`) is not an image of the page.
IMAGE_LINK = re.compile(r"(?:\]\(|src=\")\.\./docs/images/([A-Za-z0-9_.-]+\.png)")
GALAXY = [("galaxy.png", "with diffused glass", "the reference report's final image"),
          ("galaxy-clear.png", "without diffused glass", "one ray per refraction")]
THUMBNAIL = 240  # the width of an image on the page, in CSS pixels
SYSTEM_PYTHON = "/usr/bin/python3"  # Debian's, the one python3-matplotlib installs for

ROW_KEYS = {"name": str, "tracer": str, "accel": str, "threads": int, "seconds": (int, float),
            "primary": int, "secondary": int, "shadow": int, "raysPerSecond": (int, float),
            "nodesPerRay": (int, float), "speedup": (int, float)}
# The figures a row that was not rendered has as null (nodesPerRay: also a structure that does
# not count its nodes).
NULLABLE = {"seconds", "primary", "secondary", "shadow", "raysPerSecond", "nodesPerRay",
            "speedup"}


class BadInput(Exception):
    """A timing file that does not follow the schema."""


def missing(what: str) -> None:
    print(f"{PROGRAM}: missing: {what}", file=sys.stderr)


# ---- Text --------------------------------------------------------------------------------------

def inline_markdown(text: str) -> str:
    """The inline Markdown of a README paragraph as HTML: `code`, **bold**, *emphasis* and
    [links](target) (their text only: the targets are relative to the README)."""
    out = []
    for k, part in enumerate(re.split(r"(`[^`]*`)", text)):
        if k % 2:
            out.append("<code>" + html.escape(part[1:-1]) + "</code>")
            continue
        part = html.escape(part, quote=False)
        part = re.sub(r"\[([^\]]+)\]\([^)]*\)", r"\1", part)
        part = re.sub(r"\*\*(.+?)\*\*", r"<strong>\1</strong>", part)
        part = re.sub(r"(?<![\w*])\*(?!\s)(.+?)(?<!\s)\*(?![\w*])", r"<em>\1</em>", part)
        out.append(part)
    return "".join(out)


def first_paragraph(readme: str) -> str:
    """The first paragraph of prose after the title: its lines up to a blank line, joined."""
    lines: list[str] = []
    for line in readme.splitlines():
        stripped = line.strip()
        if not lines:
            if not stripped or stripped.startswith(("#", "|", "```", "<!--", "!", ">")):
                continue
        elif not stripped or stripped.startswith(("#", "|", "```")):
            break
        lines.append(stripped)
    return " ".join(lines)


def format_seconds(s: float) -> str:
    """5.70 ms, 12.3 s, 4 min 05 s, 1 h 21 min (as scripts/common.sh's rt_elapsed, with
    hours): three significant digits at most."""
    if s < 0.1:
        return f"{significant(s * 1000)} ms"
    if s < 60:
        return f"{s:.3g} s"
    if s < 3600:
        return f"{int(s // 60)} min {int(s) % 60:02d} s"
    return f"{int(s // 3600)} h {int(s) % 3600 // 60:02d} min"


def format_number(x: float) -> str:
    """Thousands separated by thin spaces, at most three decimals."""
    if isinstance(x, int) or float(x).is_integer():
        return f"{int(x):,}".replace(",", "\u2009")
    return f"{x:,.3f}".rstrip("0").rstrip(".").replace(",", "\u2009")


# ---- Images ------------------------------------------------------------------------------------

def png_size(path: Path) -> tuple[int, int] | None:
    """The width and height in a PNG's header, or None when it is not a PNG."""
    with path.open("rb") as f:
        head = f.read(24)
    if len(head) < 24 or head[:8] != b"\x89PNG\r\n\x1a\n" or head[12:16] != b"IHDR":
        return None
    return struct.unpack(">II", head[16:24])


def figure(image: Path, page_dir: Path, caption: str) -> str:
    size = png_size(image)
    width, height = size if size else (1, 1)
    shown_height = round(THUMBNAIL * height / width)
    src = Path(os.path.relpath(image, page_dir)).as_posix()
    return (f'<figure><a href="{html.escape(src)}"><img src="{html.escape(src)}" '
            f'alt="{html.escape(image.stem)}" width="{THUMBNAIL}" height="{shown_height}"></a>'
            f"<figcaption>{caption}</figcaption></figure>")


# ---- The timing chart --------------------------------------------------------------------------

def reference_seconds(row: dict) -> float | None:
    """The reference report's time for the row's render, or None."""
    return row.get("referenceSeconds")


def read_bench(path: Path) -> dict:
    """The timing file, checked against the schema. @raises BadInput naming the place."""
    try:
        bench = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as e:
        raise BadInput(f"{path}: cannot read it as JSON: {e}") from e
    if not isinstance(bench, dict):
        raise BadInput(f"{path}: expected an object {{scene, width, height, rows}}")
    for key, kind in (("scene", str), ("width", int), ("height", int), ("rows", list)):
        if not isinstance(bench.get(key), kind) or isinstance(bench.get(key), bool):
            raise BadInput(f"{path}: {key}: expected {kind.__name__}, got {bench.get(key)!r}")
    for i, row in enumerate(bench["rows"]):
        if not isinstance(row, dict):
            raise BadInput(f"{path}: rows[{i}]: expected an object")
        for key, kind in ROW_KEYS.items():
            value = row.get(key)
            if value is None and key in NULLABLE and key in row:
                continue
            if not isinstance(value, kind) or isinstance(value, bool):
                raise BadInput(f"{path}: rows[{i}].{key}: expected "
                               f"{'a number' if isinstance(kind, tuple) else kind.__name__}, "
                               f"got {value!r}")
        value = row.get("referenceSeconds")
        if value is not None and (not isinstance(value, (int, float)) or isinstance(value, bool)):
            raise BadInput(f"{path}: rows[{i}].referenceSeconds: expected null or a number, "
                           f"got {value!r}")
        value = row.get("pixelsDiffering")
        if value is not None and (not isinstance(value, int) or isinstance(value, bool)
                                  or value < 0):
            raise BadInput(f"{path}: rows[{i}].pixelsDiffering: expected null or a count >= 0, "
                           f"got {value!r}")
        if not isinstance(row.get("note", ""), str):
            raise BadInput(f"{path}: rows[{i}].note: expected str, got {row.get('note')!r}")
        for key in ("seconds", "referenceSeconds"):
            value = row.get(key)
            if value is not None and not (math.isfinite(value) and value >= 0):
                raise BadInput(f"{path}: rows[{i}].{key}: expected a number >= 0, got {value!r}")
    return bench


def significant(x: float, digits: int = 3) -> str:
    """x to `digits` significant digits, without an exponent: 1.77, 96.5, 0.265, 46400."""
    if x == 0 or not math.isfinite(x):
        return f"{x:g}"
    exponent = math.floor(math.log10(abs(x)))
    step = Decimal(1).scaleb(exponent - digits + 1)  # halves round up: 37.25 -> 37.3
    return f"{Decimal(repr(x)).quantize(step, rounding=ROUND_HALF_UP):f}"


def format_rate(x: float) -> str:
    """Rays per second with three significant digits: 134 k, 12.9 M."""
    for scale, unit in ((1e9, "G"), (1e6, "M"), (1e3, "k")):
        if x >= scale:
            return f"{significant(x / scale)} {unit}"
    return significant(x)


def same_work(row: dict, first: dict) -> bool:
    """Whether the row traces the rays of the first row: only then is a speed-up like with
    like (a stage's tracer casts other rays than the beams tracer of the reference rows)."""
    return all(row[k] == first[k] for k in ("tracer", "primary", "secondary", "shadow"))


def matplotlib_pyplot():
    """matplotlib's pyplot with the SVG backend, made reproducible (no date, fixed ids, text
    as text so that the labels stay selectable and searchable). @raises BadInput without it."""
    try:
        import matplotlib
    except ImportError as e:
        problem = ("the timing chart needs matplotlib (Debian: python3-matplotlib; "
                   f"scripts/deps.sh python3-matplotlib installs it) for {sys.executable}")
        if other := python_with_matplotlib():
            problem += f"; {other} has it: {shlex.join([other, *sys.argv])}"
        raise BadInput(problem) from e
    matplotlib.use("svg")
    import matplotlib.pyplot as plt
    matplotlib.rcParams.update({"svg.fonttype": "none", "svg.hashsalt": "rt-gallery",
                                "font.size": 11, "font.family": "DejaVu Sans"})
    return plt


def python_with_matplotlib() -> str | None:
    """SYSTEM_PYTHON when this script runs under another interpreter (a pyenv one, say) and that
    one imports matplotlib; else None. Asked only once matplotlib is missing here."""
    if sys.executable == SYSTEM_PYTHON:
        return None
    try:
        run = subprocess.run([SYSTEM_PYTHON, "-c", "import matplotlib"], stdin=subprocess.DEVNULL,
                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
    except OSError:  # no such program
        return None
    return SYSTEM_PYTHON if run.returncode == 0 else None


def svg_of(plt, fig, label: str) -> str:
    """The figure as an inline <svg> that scales to the width of its container."""
    import io
    buffer = io.StringIO()
    fig.savefig(buffer, format="svg", bbox_inches="tight", metadata={"Date": None})
    plt.close(fig)
    svg = buffer.getvalue()
    svg = svg[svg.index("<svg"):]
    svg = re.sub(r'<svg ([^>]*?)width="[^"]*" height="[^"]*"',
                 rf'<svg class="chart" role="img" aria-label="{html.escape(label)}" \1', svg,
                 count=1)
    return svg.strip()


def reference_chart(plt, bench: dict, rows: list[dict]) -> str:
    """The rows that the reference report timed: this repository's time beside the report's,
    on a log scale (they span five powers of ten)."""
    ours = [r["seconds"] for r in rows]
    theirs = [reference_seconds(r) for r in rows]
    fig, ax = plt.subplots(figsize=(7.2, 0.9 + 0.8 * len(rows)))
    y = list(range(len(rows)))
    h = 0.38
    ax.barh([v - h / 2 for v in y], ours, height=h, color="#3b6ea8",
            label=f"this repository, {bench['width']}\u00d7{bench['height']}")
    ax.barh([v + h / 2 for v in y], theirs, height=h, color="#d98c3f",
            label="the reference report (Java), 1280\u00d7720")
    for v, s in zip(y, ours):
        ax.text(s * 1.15, v - h / 2, format_seconds(s), va="center", fontsize=10)
    for v, s in zip(y, theirs):
        ax.text(s * 1.15, v + h / 2, format_seconds(s), va="center", fontsize=10)
    ax.set_xscale("log")
    low = min(ours + theirs)
    high = max(ours + theirs)
    ax.set_xlim(low / 3, high * 20)
    ax.set_yticks(y, [r["name"] for r in rows])
    ax.invert_yaxis()
    ax.set_xlabel("wall time per render, seconds (log scale)")
    ax.legend(loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=1, frameon=False)
    for side in ("top", "right"):
        ax.spines[side].set_visible(False)
    return svg_of(plt, fig, "wall time of the reference report's rows, this repository beside "
                            "the reference report")


def rate_chart(plt, bench: dict, rows: list[dict]) -> str:
    """The stages' tracers as rays per second: each casts other rays, so rays per second is
    what compares them."""
    rates = [r["raysPerSecond"] for r in rows]
    fig, ax = plt.subplots(figsize=(7.2, 0.7 + 0.45 * len(rows)))
    y = list(range(len(rows)))
    ax.barh(y, [x / 1e6 for x in rates], height=0.6, color="#3b6ea8")
    for v, x in zip(y, rates):
        ax.text(x / 1e6 * 1.02, v, f"{format_rate(x)} rays/s", va="center", fontsize=10)
    ax.set_xlim(0, max(rates) / 1e6 * 1.35 if rates else 1)
    ax.set_yticks(y, [f'{r["name"]} ({r["tracer"]})' for r in rows])
    ax.invert_yaxis()
    ax.set_xlabel("million rays per second (every ray: primary, secondary, shadow)")
    for side in ("top", "right"):
        ax.spines[side].set_visible(False)
    return svg_of(plt, fig, "rays per second of each stage's tracer")


def timing_charts(bench: dict) -> list[str]:
    """The charts of the timing: the reference report's rows, then the other rows."""
    plt = matplotlib_pyplot()
    rows = [r for r in bench["rows"] if r["seconds"] is not None]  # rendered rows only
    timed = [r for r in rows if reference_seconds(r) is not None]
    others = [r for r in rows if reference_seconds(r) is None and r["raysPerSecond"] is not None]
    out = []
    if timed:
        out.append(f"<p>The reference report's rows: {bench['scene']} at "
                   f"{bench['width']}\u00d7{bench['height']} here, at 1280\u00d7720 (a "
                   f"{significant(1280 * 720 / (bench['width'] * bench['height']))} times "
                   "larger image) in the report, in Java on its own machine.</p>")
        out.append('<figure class="chart">' + reference_chart(plt, bench, timed) + "</figure>")
    if others:
        out.append("<p>Each stage's tracer on the same scene: they cast different rays, so "
                   "rays per second compares them.</p>")
        out.append('<figure class="chart">' + rate_chart(plt, bench, others) + "</figure>")
    return out


def timing_table(bench: dict) -> str:
    head = ("name", "tracer", "acceleration", "threads", "time", "primary rays",
            "secondary rays", "shadow rays", "rays/s", "nodes/ray", "speed-up",
            "the reference report", "pixels differing", "note")
    first = bench["rows"][0] if bench["rows"] else None
    out = ['<div class="table"><table><thead><tr>' +
           "".join(f"<th>{h}</th>" for h in head) + "</tr></thead><tbody>"]
    for r in bench["rows"]:
        reference = reference_seconds(r)
        speedup = (f'{significant(r["speedup"])}\u00d7'
                   if r["speedup"] is not None and same_work(r, first) else "—")

        def shown(value, form) -> str:
            return "—" if value is None else form(value)
        pixels = r.get("pixelsDiffering")
        cells = (html.escape(r["name"]), html.escape(r["tracer"]), html.escape(r["accel"]),
                 str(r["threads"]), shown(r["seconds"], format_seconds),
                 shown(r["primary"], format_number), shown(r["secondary"], format_number),
                 shown(r["shadow"], format_number), shown(r["raysPerSecond"], format_rate),
                 shown(r["nodesPerRay"], significant), speedup,
                 format_seconds(reference) if reference is not None else "—",
                 shown(pixels, format_number), html.escape(r.get("note", "")))
        out.append("<tr>" + "".join(f"<td>{c}</td>" for c in cells) + "</tr>")
    out.append("</tbody></table></div>")
    out.append("<p>The speed-up is the first row's time over the row's, shown where the row "
               "traces the same rays as the first (—: other work). Pixels differing: from the "
               "first row's image, for the rows of its tracer; the project's structures differ "
               "in none. Embree tests its boxes and its spheres, triangles and quads in float: "
               "a ray that grazes a shape's edge can miss it there, where the exact test hits "
               "it; every hit Embree offers is checked and ordered by the project's exact test, "
               "so only such rays can change a pixel.</p>")
    return "\n".join(out)


# ---- The page ----------------------------------------------------------------------------------

def stage_folders(root: Path) -> list[Path]:
    """stageNN_* then miniN_*, each by number: the course's order."""
    found = [p for p in root.iterdir() if p.is_dir() and STAGE_FOLDER.match(p.name)]

    def key(p: Path) -> tuple[int, int]:
        m = STAGE_FOLDER.match(p.name)
        return (0 if m.group(1) == "stage" else 1, int(m.group(2)))
    return sorted(found, key=key)


def stage_section(folder: Path, root: Path, page_dir: Path, shown: set[str]) -> str:
    readme = folder / "README.md"
    rel = Path(os.path.relpath(readme, page_dir)).as_posix()
    out = [f'<section class="stage" id="{folder.name}">']
    if not readme.is_file():
        missing(f"{folder.name}/README.md")
        out.append(f"<h3>{folder.name}</h3><p class=\"note\">No README yet.</p></section>")
        return "\n".join(out)
    text = readme.read_text(encoding="utf-8")
    out.append(f'<h3><a href="{html.escape(rel)}">{folder.name}</a></h3>')
    out.append(f"<p>{inline_markdown(first_paragraph(text))}</p>")
    figures = []
    for name in dict.fromkeys(IMAGE_LINK.findall(text)):  # in the README's order, once each
        image = root / "docs" / "images" / name
        if not image.is_file():
            missing(f"docs/images/{name} (linked by {folder.name}/README.md)")
            continue
        shown.add(name)
        figures.append(figure(image, page_dir, f"<code>{html.escape(image.stem)}</code>"))
    if figures:
        out.append('<div class="images">' + "".join(figures) + "</div>")
    out.append("</section>")
    return "\n".join(out)


def page(root: Path, bench_path: Path, page_dir: Path) -> str:
    bench = read_bench(bench_path) if bench_path.is_file() else None  # first: it may be bad
    images = root / "docs" / "images"
    shown: set[str] = set()
    body = ["<h1>A staged ray tracer: the gallery</h1>",
            "<p>Generated by <code>scripts/make-gallery.py</code> from the stages' READMEs, "
            "<code>docs/images/</code> and the timing of <code>rt bench --json</code>. "
            "The stages, in the course's order, each with the first paragraph of its README "
            "and the images it shows:</p>",
            '<h2 id="stages">The stages</h2>']
    body += [stage_section(f, root, page_dir, shown) for f in stage_folders(root)]

    body.append('<h2 id="galaxy">The galaxy in a glass box, with and without diffused '
                'glass</h2>')
    pair = []
    for name, which, detail in GALAXY:
        if (images / name).is_file():
            shown.add(name)
            pair.append(figure(images / name, page_dir, f"{which} ({detail})"))
        else:
            missing(f"docs/images/{name} (the galaxy {which})")
    body.append('<div class="images">' + "".join(pair) + "</div>" if pair else
                '<p class="note">Not rendered yet.</p>')

    rest = sorted(p for p in images.glob("*.png") if p.name not in shown) if images.is_dir() \
        else []
    if rest:
        body.append('<h2 id="references">Every other image</h2>')
        body.append("<p>An image named after a scene of <code>rt list</code> is its reference "
                    "image, <code>rt render NAME --width 500</code>: compare yours with "
                    "<code>rt compare mine.png docs/images/NAME.png</code>.</p>")
        body.append('<div class="images">' + "".join(
            figure(p, page_dir, f"<code>{html.escape(p.stem)}</code>") for p in rest) + "</div>")

    body.append('<h2 id="timing">Timing across stages</h2>')
    if bench:
        body += timing_charts(bench)
        body.append(timing_table(bench))
    else:
        where = os.path.relpath(bench_path, root) if bench_path.is_relative_to(root) \
            else str(bench_path)
        missing(f"{where} (the timing: rt bench --json > docs/bench.json)")
        body.append('<p class="note">No timing yet: <code>rt bench --json &gt; docs/bench.json'
                    "</code>, then run <code>scripts/make-gallery.py</code> again.</p>")
    style = Path(os.path.relpath(STYLESHEET, page_dir)).as_posix()
    return ("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
            "<title>A staged ray tracer: the gallery</title>\n"
            f'<link rel="stylesheet" href="{html.escape(style)}">\n</head>\n<body>\n' +
            "\n".join(body) + "\n</body>\n</html>\n")


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(prog="scripts/make-gallery.py",
                                     description="Writes the gallery page, docs/index.html.")
    parser.add_argument("--root", type=Path, default=Path(__file__).resolve().parent.parent,
                        help="the repository (default: this script's)")
    parser.add_argument("--bench", type=Path,
                        help="the timing, as rt bench --json writes it (default: "
                             "ROOT/docs/bench.json)")
    parser.add_argument("-o", "--output", type=Path,
                        help="where to write the page (default: ROOT/docs/index.html)")
    args = parser.parse_args(argv)
    root = args.root.resolve()
    if not root.is_dir():
        print(f"{PROGRAM}: --root: no directory '{args.root}'", file=sys.stderr)
        return 2
    output = (args.output or root / "docs" / "index.html").resolve()
    bench = (args.bench or root / "docs" / "bench.json").resolve()
    # The default timing file may be missing (the page says so); one the user named may not.
    if args.bench and not bench.is_file():
        why = "it is a directory" if bench.is_dir() else "no such file"
        print(f"{PROGRAM}: --bench: cannot read '{args.bench}': {why}", file=sys.stderr)
        return 2
    # As rt says it: the option, then the path as given.
    cannot_write = f"-o: cannot write '{args.output}'" if args.output else \
        f"cannot write '{output}'"
    if problem := output_problem(output):
        print(f"{PROGRAM}: {cannot_write}: {problem}", file=sys.stderr)
        return 2
    written = Written()
    try:
        try:
            text = page(root, bench, output.parent)
        except BadInput as e:
            print(f"{PROGRAM}: {e}", file=sys.stderr)
            return 2
        try:
            write_whole(output, text, written)
        except OSError as e:
            print(f"{PROGRAM}: {cannot_write}: {e.strerror or e}", file=sys.stderr)
            return 1
        print(f"{PROGRAM}: wrote {output}")
    except KeyboardInterrupt:  # write_whole leaves no .tmp, and the page whole or not at all
        print(written.interrupted(PROGRAM, output), file=sys.stderr)
        return EXIT_INTERRUPTED
    return 0


if __name__ == "__main__":
    sys.exit(run_command_line(main, sys.argv[1:]))

"""Sphinx configuration of the graspcompass documentation.

Markdown pages (MyST) with the furo theme, the gallery of the paper's figures
(sphinx-gallery, scripts in ``../gallery``), the API reference (autodoc +
napoleon, numpydoc style) and pages generated at build time into
``_generated/`` (never edited by hand, ignored by git):

- ``proof-report.md``: ``graspcompass verify --markdown``, run in-process;
- ``fig6-steps.md``: the construction protocol of the Fig. 6 grasp, each
  step linked to the paper's equation and to the gallery figure;
- ``main-job/``: what ``graspcompass`` (the README's first command) writes.

Build: ``sphinx-build -W --keep-going -b html docs docs/_build/html``
(``.ci/build-docs.sh``).
"""

from __future__ import annotations

import contextlib
import io
import os
import re
import shutil
import sys
from pathlib import Path

DOCS = Path(__file__).resolve().parent
ROOT = DOCS.parent
GENERATED = DOCS / "_generated"
sys.path.insert(0, str(ROOT / "src"))  # the package as checked out, installed or not
os.environ.setdefault("MPLBACKEND", "agg")

import matplotlib  # noqa: E402

import graspcompass  # noqa: E402

# The gallery shows the library's standalone Figures and animations through pyplot with
# ``plt.figure(fig)``, which registers a Figure made without pyplot (Matplotlib 3.11).
if tuple(int(p) for p in re.findall(r"\d+", matplotlib.__version__)[:2]) < (3, 11):
    raise RuntimeError(f"the documentation needs matplotlib >= 3.11 (plt.figure(fig) on a "
                       f"standalone Figure); found {matplotlib.__version__}")

# -- project -----------------------------------------------------------------------------------
project = "graspcompass"
author = "graspcompass developers"
copyright = "graspcompass developers (MIT licence)"
version = release = graspcompass.__version__

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.napoleon",
    "sphinx.ext.mathjax",
    "sphinx.ext.viewcode",
    "sphinx_gallery.gen_gallery",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "_generated/**", "**/GALLERY_HEADER.rst", "Thumbs.db",
                    ".DS_Store"]
# a broken cross-reference to our own pages is an error (-W); references into Python,
# numpy or sympy from docstrings stay plain text (no intersphinx: the build is offline)
nitpicky = False

# -- MyST --------------------------------------------------------------------------------------
myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence", "deflist", "attrs_inline"]
myst_heading_anchors = 3
myst_dmath_double_inline = True

# -- HTML --------------------------------------------------------------------------------------
html_theme = "furo"
html_title = f"graspcompass {release}"
html_static_path = ["_static"]
html_css_files = ["graspcompass.css"]
html_show_sourcelink = False
html_favicon = "_static/favicon.svg"
html_theme_options = {
    "sidebar_hide_name": False,
    "navigation_with_keys": True,
}

# MathJax: the copy Debian ships (package libjs-mathjax) when it is installed, so that the
# pages render their formulas offline; otherwise Sphinx's default (a CDN).
_MATHJAX = Path("/usr/share/javascript/mathjax")
_MATHJAX_PARTS = ("MathJax.js", "config/TeX-AMS_SVG.js", "extensions", "jax/input/TeX",
                  "jax/element", "jax/output/SVG/jax.js", "jax/output/SVG/autoload",
                  "jax/output/SVG/fonts/TeX", "localization/en")


def _local_mathjax() -> bool:
    """Copy the parts of Debian's MathJax 2 that TeX input with SVG output needs."""
    if not (_MATHJAX / "MathJax.js").is_file():
        return False
    dest = GENERATED / "mathjax-static" / "mathjax"
    if not (dest / "MathJax.js").is_file():
        for part in _MATHJAX_PARTS:
            src = _MATHJAX / part
            if not src.exists():
                return False
            if src.is_dir():
                shutil.copytree(src, dest / part, dirs_exist_ok=True)
            else:
                (dest / part).parent.mkdir(parents=True, exist_ok=True)
                shutil.copy2(src, dest / part)
    return True


if _local_mathjax():
    html_static_path.append("_generated/mathjax-static")
    mathjax_path = "mathjax/MathJax.js?config=TeX-AMS_SVG"
    mathjax2_config = {
        # MyST marks its pages ``tex2jax_ignore`` and its math ``math``: process that
        "tex2jax": {"inlineMath": [["\\(", "\\)"]], "displayMath": [["\\[", "\\]"]],
                    "processRefs": False, "processEnvironments": False,
                    "processClass": "tex2jax_process|mathjax_process|math|output_area"},
        "SVG": {"font": "TeX"},
        "showMathMenu": False,
        "messageStyle": "none",
    }

# -- autodoc (numpydoc style through napoleon) -------------------------------------------------
autodoc_typehints = "description"
autodoc_typehints_description_target = "documented_params"
autodoc_member_order = "bysource"
autodoc_default_options = {"members": True, "show-inheritance": True, "no-value": True}
autodoc_preserve_defaults = True
autoclass_content = "class"
napoleon_google_docstring = False
napoleon_numpy_docstring = True
napoleon_use_rtype = False
napoleon_use_param = True
napoleon_attr_annotations = True
napoleon_use_ivar = True  # "Attributes" as fields: no second description of dataclass fields

# -- the gallery -------------------------------------------------------------------------------
sphinx_gallery_conf = {
    "examples_dirs": "../gallery",
    "gallery_dirs": "auto_examples",
    "filename_pattern": r"/plot_",
    "within_subsection_order": "FileNameSortKey",
    "matplotlib_animations": (True, "jshtml"),
    "image_scrapers": ("matplotlib",),
    "remove_config_comments": True,
    "abort_on_example_error": True,
    "write_computation_times": False,
    "show_signature": False,
    "capture_repr": ("_repr_html_", "__repr__"),
    # a block that ends in a drawing call must not print the artist's repr
    "ignore_repr_types": r"matplotlib|list|tuple|dict|NoneType",
    "min_reported_time": 1,
}


# -- pages generated at build time -------------------------------------------------------------
def _write(path: Path, text: str) -> None:
    """Write ``text`` unless the file already holds it (keeps incremental builds quiet)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    if not path.is_file() or path.read_text(encoding="utf-8") != text:
        path.write_text(text, encoding="utf-8")


def _proof_report() -> None:
    """``graspcompass verify --markdown _generated/proof-report.md`` (about 5 s)."""
    from graspcompass.cli import main

    out = GENERATED / "proof-report.md"
    tmp = GENERATED / "proof-report.tmp.md"
    status = main(["verify", "--markdown", str(tmp), "--quiet"])
    text = tmp.read_text(encoding="utf-8")
    tmp.unlink()
    if status != 0:
        raise RuntimeError("graspcompass verify failed (an UNDECIDED claim, or a refuted "
                           "claim without a proved correction): see the proof report")
    _write(out, text)


# The paper's equations that paper.md gives a target ``(eq-N)=`` to.
_EQUATIONS = {int(n) for n in re.findall(r"^\(eq-(\d+)\)=$",
                                         (DOCS / "paper.md").read_text(encoding="utf-8"), re.M)}
_FIGURE_PAGES = {
    "2": "auto_examples/plot_01_fig2_grasp_and_friction_cones",
    "3": "auto_examples/plot_02_fig3_thales_circle",
    "4": "auto_examples/plot_03_fig4_drawing_V1_to_V4",
    "5": "auto_examples/plot_04_fig5_circles_and_envelope",
    "6": "auto_examples/plot_05_fig6_construction_vs_computer",
}


def link_reference(ref: str) -> str:
    """The paper reference of a protocol step as MyST, with links.

    Each equation number after ``eq.``/``eqs.`` links to its target in
    ``paper.md`` (``eq. (28)-(29)`` gives two links), ``Fig. 4(a)`` links to
    the gallery page of that figure; section numbers stay text.

    >>> link_reference("§3.3 V1 step (1), eq. (28)-(29)")
    '§3.3 V1 step (1), eq. {ref}`(28) <eq-28>`-{ref}`(29) <eq-29>`'
    """
    def number(m: re.Match[str]) -> str:
        n = int(m.group(1))
        return f"{{ref}}`({n}) <eq-{n}>`" if n in _EQUATIONS else m.group(0)

    def equations(m: re.Match[str]) -> str:
        return m.group(1) + re.sub(r"\((\d+)\)", number, m.group(2))

    def figure(m: re.Match[str]) -> str:
        page = _FIGURE_PAGES.get(m.group(1))
        return f"{{doc}}`{m.group(0)} </{page}>`" if page else m.group(0)

    out = re.sub(r"(eqs?\. )(\(\d+\)(?:[-–/, ]+\(\d+\))*)", equations, ref)
    return re.sub(r"Fig\. (\d)(\([a-d]\))?", figure, out)


def _steps_table() -> None:
    """The protocol of the Fig. 6 grasp as a Markdown table (construction page)."""
    from graspcompass import Grasp, internal_force_diagram
    from graspcompass.construction import describe

    c = internal_force_diagram(Grasp.preset("fig6"))
    rows = ["| # | object | instrument | what is drawn | paper | exact value |",
            "| --: | --- | --- | --- | --- | --- |"]
    for s in c.steps:
        value = describe(s.obj)
        if len(value) > 80:
            value = value[:77] + "…"
        cells = [str(s.index), f"`{s.name}`", s.instrument, _md(s.caption),
                 link_reference(s.ref), _md(value)]
        rows.append("| " + " | ".join(cells) + " |")
    _write(GENERATED / "fig6-steps.md", "\n".join(rows) + "\n")


def _md(text: str) -> str:
    """Plain text safe in a Markdown table cell."""
    return re.sub(r"([|*_`\\[\]<>])", r"\\\1", text)


def _main_job() -> None:
    """Run ``graspcompass`` in ``_generated/``; keep its files and an excerpt of its output
    (the givens, the drawing of V1 and the envelope)."""
    from graspcompass.cli import main

    buf = io.StringIO()
    here = os.getcwd()
    os.chdir(GENERATED)
    try:
        with contextlib.redirect_stdout(buf):
            status = main([])
    finally:
        os.chdir(here)
    if status != 0:
        raise RuntimeError("the main job `graspcompass` failed")
    keep, gap = [], False
    for line in buf.getvalue().rstrip().splitlines():
        row = re.match(r"(\d+) ", line)
        if row and int(row.group(1)) not in (0, 1, 2, 3, 4, 12, 13, 14, 15, 16, 17, 46):
            if not gap:
                keep.append("...")
            gap = True
            continue
        gap = False
        keep.append(line if len(line) < 150 else line[:147] + "...")
    _write(GENERATED / "main-job.txt", "\n".join(keep) + "\n")


# numpydoc allows no free text inside a "Parameters" section: a paragraph after the last
# parameter is read by napoleon as more parameters (a docutils warning, fatal with -W).
# Until such a docstring is fixed in the source, give that paragraph a "Notes" heading.


def _generate(app: object) -> None:
    GENERATED.mkdir(exist_ok=True)
    _proof_report()
    _steps_table()
    _main_job()


def setup(app: object) -> dict[str, object]:
    # the generated files are read later, with the other sources
    app.connect("builder-inited", _generate, priority=400)  # type: ignore[attr-defined]
    # before napoleon (priority 500) turns the numpydoc sections into fields
    return {"parallel_read_safe": True, "parallel_write_safe": True}

# SPDX-License-Identifier: BSD-3-Clause
# Sphinx configuration of kinestat's documentation site. Not run from here: build_site.py
# stages these pages with docs/*.md (as guide/), the generated gallery and the C++ reference
# (Doxygen, as cpp/) and runs sphinx-build on the staged copy (`cmake --build <build> --target docs`).
import os

project = "kinestat"
author = "the kinestat authors"
copyright = "2026, the kinestat authors (BSD-3-Clause)"
version = release = os.environ.get("KINESTAT_VERSION", "")
extensions = ["myst_parser", "sphinx.ext.autodoc", "sphinx.ext.napoleon"]
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
# Anchors of Markdown headings, so that links such as network.md#large-networks resolve.
myst_heading_anchors = 3
myst_enable_extensions = ["colon_fence"]
exclude_patterns = ["_build"]
html_theme = "alabaster"
html_static_path = ["_static"]
html_css_files = ["site.css"]
html_title = f"kinestat {release}"
html_theme_options = {"description": "How free and how constrained is a mechanism, a flexure or a structure?",
                      "fixed_sidebar": True, "page_width": "1100px", "sidebar_width": "230px"}
autodoc_member_order = "bysource"
# Pages link the repository's files (../examples/..., ../README.md): not pages of this site.
suppress_warnings = ["myst.xref_missing", "myst.header"]

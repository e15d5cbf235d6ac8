# The manual of RISE, the Realistic Image Synthesis Environment: a book in
# English and Brazilian Portuguese, built by `cmake --build build --target
# manual` (docs/manual/build-manual), which sets where the rise program and
# the build's files are.
import os
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent / "_ext"))

project = "RISE"
author = "the RISE authors"
copyright = "2006-2025, the RISE authors"
extensions = ["rise_manual"]

root_doc = "index"
exclude_patterns = ["tests", "locales", "scenes", "README.md"]
templates_path = ["_templates"]
html_static_path = ["_static"]
html_css_files = ["rise.css"]

# The languages of the book; each page links to itself in the others.
language = "en"
locale_dirs = ["locales/"]
gettext_compact = False
gettext_location = False
gettext_uuid = False
rise_languages = [("en", "English"), ("pt_BR", "Português (Brasil)")]

html_theme = "furo"
html_title = "RISE"
html_last_updated_fmt = None
html_show_sourcelink = False
html_copy_source = False
html_permalinks_icon = "#"
html_use_index = False
html_sidebars = {
    "**": [
        "sidebar/brand.html",
        "sidebar/languages.html",
        "sidebar/search.html",
        "sidebar/scroll-start.html",
        "sidebar/navigation.html",
        "sidebar/scroll-end.html",
    ]
}

rise_repository = str(Path(__file__).resolve().parents[2])
rise_executable = os.environ.get("RISE_EXECUTABLE", "")
rise_cache = os.environ.get("RISE_MANUAL_CACHE", "")
rise_manifest = ""

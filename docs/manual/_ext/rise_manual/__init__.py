"""The Sphinx extension of RISE's manual: figures that RISE renders when the
manual is built, commands and scenes that its tests run, tables of scene keys
held to the loader, and the language switch."""

from . import manifest
from .commands import RiseCommand, RiseScene, counter_role
from .figures import RiseFigure
from .languages import add_language_links
from .scene_keys import SceneKeys
from .theme_scripts import bundle_furo_script


def setup(app):
    app.add_config_value("rise_executable", "", "env")
    app.add_config_value("rise_repository", "", "env")
    app.add_config_value("rise_cache", "", "env")
    app.add_config_value("rise_manifest", "", "env")
    app.add_config_value("rise_languages", [("en", "English")], "html")
    app.add_directive("rise-figure", RiseFigure)
    app.add_directive("rise-command", RiseCommand)
    app.add_directive("rise-scene", RiseScene)
    app.add_directive("scene-keys", SceneKeys)
    app.add_role("counter", counter_role)
    app.connect("env-purge-doc", manifest.purge_page)
    app.connect("env-merge-info", manifest.merge_pages)
    app.connect("build-finished", manifest.write)
    app.connect("html-page-context", add_language_links)
    app.connect("build-finished", bundle_furo_script)
    return {"version": "1", "parallel_read_safe": False, "parallel_write_safe": True}

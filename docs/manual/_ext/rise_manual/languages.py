"""The language switch on every page: a link to the same page in each other
language of the book, as the original RISE manual had.

The languages are built side by side (`<output>/en/...`, `<output>/pt_BR/...`),
so the same page in another language is at a path relative to this one, and
the link works from the files as well as from a server.
"""


def add_language_links(app, pagename, templatename, context, doctree):
    depth = pagename.count("/") + 1
    links = []
    for code, name in app.config.rise_languages:
        links.append(
            {
                "code": code,
                "name": name,
                "current": code == app.config.language,
                "url": "../" * depth + f"{code}/{pagename}.html",
            }
        )
    context["rise_languages"] = links

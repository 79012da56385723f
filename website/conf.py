"""Sphinx configuration of the course website (website/build.py stages the pages and runs it).

Everything is served from the site itself: the theme's CSS, fonts and scripts come with
sphinx-book-theme, MathJax is a local copy (_static/mathjax, from npm), and no page asks for
anything on another host when it is viewed.
"""
project = "Graphics and Visualization: the course"
author = "the course team"
copyright = "2026, the course team"

extensions = ["myst_nb"]
root_doc = "index"
exclude_patterns = ["_originals/**", "**.ipynb_checkpoints"]

# the stored outputs are the pages: nothing is executed
nb_execution_mode = "off"
nb_merge_streams = True
nb_render_markdown_format = "myst"          # the exercises' Markdown outputs hold $math$
nb_output_stderr = "remove"                 # warnings printed while a lesson ran
myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence", "attrs_inline"]
myst_heading_anchors = 3
myst_dmath_double_inline = True
myst_update_mathjax = False        # MathJax also reads the raw-HTML questions (see mathjax3_config)

# MathJax from the site, not from a CDN
mathjax_path = "mathjax/tex-mml-chtml.js"
# $…$ as well: the check-yourself questions are raw HTML (<details><summary>), which MyST does not
# parse, so their mathematics reaches the page as $…$ and MathJax typesets it there, as
# JupyterLab does (MathJax leaves <pre> and <code> alone)
mathjax3_config = {"tex": {"inlineMath": [["$", "$"], ["\\(", "\\)"]],
                           "displayMath": [["$$", "$$"], ["\\[", "\\]"]],
                           "processEscapes": True},
                   "options": {"enableMenu": True}}

html_theme = "sphinx_book_theme"
html_title = "Graphics and Visualization"
html_static_path = ["_static"]
html_css_files = ["course.css"]
html_js_files = ["course.js"]
html_last_updated_fmt = None
html_copy_source = False            # the download is the original notebook, not the page's copy
html_show_sourcelink = False
html_theme_options = {
    "home_page_in_toc": True,
    "show_toc_level": 2,
    "use_download_button": False,
    "use_fullscreen_button": False,
    "use_repository_button": False,
    "navigation_with_keys": True,
    "search_bar_text": "Search the course…",
    "show_prev_next": True,
}
html_context = {"default_mode": "auto"}

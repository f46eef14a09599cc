# SPDX-License-Identifier: BSD-3-Clause
"""Reports in a notebook (issue 39, item 3): `_repr_html_` is one sandboxed iframe whose whole
document is in `srcdoc`, so no style, id or script of a report reaches the notebook or another
report."""

import html
import html.parser

import pytest

import kinestat

pytestmark = pytest.mark.skipif(not kinestat.html_built_in(), reason="kinestat was built without the HTML viewer")


class _Outer(html.parser.HTMLParser):
    # The markup as the notebook sees it: elements and their attributes (srcdoc is one attribute).
    def __init__(self):
        super().__init__()
        self.elements = []

    def handle_starttag(self, tag, attrs):
        self.elements.append((tag, dict(attrs)))


def outer(markup):
    parser = _Outer()
    parser.feed(markup)
    parser.close()
    return parser.elements


def test_the_notebook_repr_is_one_isolated_iframe_holding_the_report(examples):
    result = kinestat.analyze(examples / "braced-square.yaml")
    markup = result._repr_html_()
    elements = outer(markup)
    assert [tag for tag, _ in elements] == ["iframe"]
    attributes = elements[0][1]
    assert attributes["srcdoc"] == result.html()  # the whole report, escaped in the attribute
    # Scripts run, but in an opaque origin: no access to the notebook's page or storage.
    assert "allow-scripts" in attributes["sandbox"].split() and "allow-same-origin" not in attributes["sandbox"]
    # Nothing of the report is markup of the notebook: its <style>, <script> and ids are text
    # inside the attribute.
    assert markup.count("<") == 2 and markup.startswith("<iframe ") and markup.endswith("></iframe>")
    assert html.unescape(markup).count("<script") == result.html().count("<script") > 0


def test_two_reports_in_one_notebook_are_independent(examples):
    first = kinestat.analyze(examples / "braced-square.yaml")
    second = kinestat.analyze(examples / "davies-2-circuit.yaml")
    documents = [outer(result._repr_html_())[0][1]["srcdoc"] for result in (first, second)]
    # Each frame holds its own report with its own verdict, and only that one.
    assert first.summary in html.unescape(documents[0]) and first.summary not in html.unescape(documents[1])
    assert second.summary in html.unescape(documents[1]) and second.summary not in html.unescape(documents[0])
    # Both reports use the same element ids and global names, harmless only because each
    # lives in its own document.
    assert 'id="summary"' in documents[0] and 'id="summary"' in documents[1]
    assert outer(first._repr_html_() + second._repr_html_()) == [("iframe", outer(first._repr_html_())[0][1]),
                                                                 ("iframe", outer(second._repr_html_())[0][1])]


def test_the_iframe_height_is_chosen():
    result = kinestat.Framework([[0, 0], [1, 0], [0, 1]], bars=[[0, 1], [1, 2], [2, 0]], supports={0: "fixed", 1: ["y"]}).analyze()
    assert "height: 480px" in outer(result.iframe(height=480))[0][1]["style"]

#!/usr/bin/python3
"""report.html as a reader's browser shows it: Debian's headless Chromium loads the page and dumps
its DOM, and the test reads that DOM.
  report_html_render_test.py CHROMIUM [--binary SIMPSON_VERIFY] REPORT_DIR...
With --binary, a fresh report of the quick scene is checked too. For each report directory:
  - every internal link (href="#x") resolves to an element with id x, and every claim has one;
  - every local link or image (href, src) names a file of the directory;
  - every expression the report shows (each claim's statement, correction and note, and the TeX
    and GiNaC forms of the formulas read from the paper) appears verbatim in the rendered text: a
    '*' read as emphasis or a D[0](V) read as a link breaks it;
  - no <em> or <a> inside a <code> element or inside those expressions;
  - the verdicts are coloured (a class per verdict).
Exit 0 when all hold, 1 otherwise (each failure named)."""
import html.parser
import json
import os
import re
import subprocess
import sys
import tempfile
import urllib.parse

chromium, directories = sys.argv[1], sys.argv[2:]
failures = 0
work = tempfile.TemporaryDirectory()
if directories[:1] == ["--binary"]:
    binary, directories = directories[1], directories[2:]
    fresh = os.path.join(work.name, "quick")
    done = subprocess.run([binary] + os.environ.get("SIMPSON_VERIFY_ARGS", "").split() + ["--scene", "quick", "--no-timing", "--quiet", "--out", fresh], capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"FAIL the quick scene did not run: exit {done.returncode}: {done.stderr[-400:]}")
    directories.append(fresh)


def fail(message):
    global failures
    failures += 1
    print("FAIL " + message)


class Dom(html.parser.HTMLParser):
    """The ids, links, images and text of a page; the text of <code> elements apart."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.ids, self.links, self.sources, self.classes = set(), [], [], set()
        self.text, self.code_text, self.stack = [], [], []
        self.inline_in_code = 0

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if "id" in a:
            self.ids.add(a["id"])
        if "class" in a:
            self.classes.update(a["class"].split())
        if tag == "a" and "href" in a:
            self.links.append(a["href"])
        if tag == "img" and "src" in a:
            self.sources.append(a["src"])
        if tag in ("em", "a", "strong") and "code" in self.stack:
            self.inline_in_code += 1
        if tag not in ("br", "img", "hr", "meta", "input"):
            self.stack.append(tag)

    def handle_endtag(self, tag):
        if tag in self.stack:
            while self.stack and self.stack.pop() != tag:
                pass

    def handle_data(self, data):
        self.text.append(data)
        if "code" in self.stack:
            self.code_text.append(data)


def normalized(text):
    return re.sub(r"\s+", " ", text).strip()


def dump_dom(page):
    with tempfile.TemporaryDirectory() as profile:
        done = subprocess.run([chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                               "--disable-component-update", "--disable-sync", "--no-first-run", "--disable-quic",
                               f"--user-data-dir={profile}", "--dump-dom", "file://" + os.path.abspath(page)],
                              capture_output=True, text=True, timeout=120)
    if done.returncode != 0 or "<body" not in done.stdout:
        sys.exit(f"FAIL chromium could not render {page}: exit {done.returncode}: {done.stderr[-400:]}")
    return done.stdout


for directory in directories:
    report = json.load(open(os.path.join(directory, "report.json")))
    dom = Dom()
    dom.feed(dump_dom(os.path.join(directory, "report.html")))
    text = normalized("".join(dom.text))
    code = normalized(" ".join(dom.code_text))
    where = os.path.basename(os.path.normpath(directory))
    for href in dom.links + dom.sources:
        if href.startswith("#"):
            if urllib.parse.unquote(href[1:]) not in dom.ids:
                fail(f"{where}: link {href} goes nowhere (no element with that id)")
        elif not re.match(r"^(https?:|mailto:|data:)", href):
            if not os.path.isfile(os.path.join(directory, urllib.parse.unquote(href))):
                fail(f"{where}: link {href} names no file of the report")
    for claim in report["claims"]:
        if claim["id"] not in dom.ids:
            fail(f"{where}: claim {claim['id']} has no anchor")
        for key in ("statement", "correction", "note"):
            if key in claim and normalized(claim[key]) not in text:
                fail(f"{where}: claim {claim['id']}: its {key} is not shown intact: {claim[key][:100]}")
        for formula in claim.get("printed", {}).get("formulas", []):
            for shown in [formula["tex"]] + formula["parsed"]:
                if normalized(shown) not in code:
                    fail(f"{where}: claim {claim['id']}: formula not shown intact in code: {shown[:100]}")
    if dom.inline_in_code:
        fail(f"{where}: {dom.inline_in_code} <em>, <strong> or <a> inside <code>")
    verdicts = {c["verdict"] for c in report["claims"]}
    for v in verdicts:
        if f"verdict-{v}" not in dom.classes:
            fail(f"{where}: verdict {v} is not coloured (no class verdict-{v})")
    print(f"checked {where}: {len(dom.links)} links, {len(dom.ids)} ids, {len(report['claims'])} claims")

print(f"{len(directories)} reports checked, {failures} failures")
sys.exit(1 if failures else 0)

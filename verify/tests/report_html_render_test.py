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
  - the verdicts are coloured (a class per verdict);
  - a table of contents links every <h2>;
  - the TeX is rendered by KaTeX (katex/ beside the page): every TeX code span is rendered, but a
    quote cut short (ending in "…"), and the TeX shown stays in the page (KaTeX's annotation);
  - at 1400 px the page does not overflow horizontally (a probe script measures it in a copy).
Exit 0 when all hold, 1 otherwise (each failure named)."""
import html.parser
import json
import os
import re
import shutil
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
    # Not certified: the page shows a certificate checked or only exported alike, and coqc's run
    # is coq.certificates'.
    done = subprocess.run([binary] + os.environ.get("SIMPSON_VERIFY_ARGS", "").split() + ["--scene", "quick", "--no-timing", "--no-certify", "--quiet", "--out", fresh], capture_output=True, text=True)
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
        self.h2, self.contents_links, self.tex_left, self.rendered = 0, [], [], 0
        self.in_contents = self.in_tex = self.in_annotation = False

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
        classes = a.get("class", "").split()
        if tag == "h2":
            self.h2 += 1
        if tag == "nav" and "contents" in classes:
            self.in_contents = True
        if tag == "a" and self.in_contents:
            self.contents_links.append(a.get("href", ""))
        if tag == "code" and "tex" in classes:
            self.in_tex = True
            self.tex_left.append("")
        if tag == "span" and "katex" in classes:
            self.rendered += 1
        if tag == "annotation":
            self.in_annotation = True
        if tag not in ("br", "img", "hr", "meta", "input"):
            self.stack.append(tag)

    def handle_endtag(self, tag):
        if tag == "nav":
            self.in_contents = False
        if tag == "code":
            self.in_tex = False
        if tag == "annotation":
            self.in_annotation = False
        if tag in self.stack:
            while self.stack and self.stack.pop() != tag:
                pass

    def handle_data(self, data):
        self.text.append(data)
        if "code" in self.stack or self.in_annotation:
            self.code_text.append(data)
        if self.in_tex:
            self.tex_left[-1] += data


def normalized(text):
    return re.sub(r"\s+", " ", text).strip()


def dump_dom(page):
    with tempfile.TemporaryDirectory() as profile:
        done = subprocess.run([chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                               "--disable-component-update", "--disable-sync", "--no-first-run", "--disable-quic",
                               "--window-size=1400,3000", "--virtual-time-budget=5000",
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
    if dom.h2 and len(dom.contents_links) != dom.h2:
        fail(f"{where}: the table of contents links {len(dom.contents_links)} of the {dom.h2} sections")
    has_katex = os.path.isfile(os.path.join(directory, "katex", "katex.min.js"))
    if has_katex:
        if dom.rendered == 0:
            fail(f"{where}: katex/ is beside the page, and no TeX was rendered")
        for left in dom.tex_left:
            if not left.rstrip().endswith("…"):
                fail(f"{where}: TeX left unrendered, not a quote cut short: {left[:100]}")
    # The page's width at 1400 px, measured by a probe script in a copy of the directory.
    with tempfile.TemporaryDirectory() as copy:
        target = os.path.join(copy, "report")
        shutil.copytree(directory, target)
        page = open(os.path.join(target, "report.html"), encoding="utf-8").read()
        probe = ("<script>window.addEventListener('load',function(){document.body.setAttribute('data-width',"
                 "document.documentElement.clientWidth+' '+document.documentElement.scrollWidth);});</script>")
        open(os.path.join(target, "probe.html"), "w", encoding="utf-8").write(page.replace("</body>", probe + "</body>"))
        measured = re.search(r'data-width="(\d+) (\d+)"', dump_dom(os.path.join(target, "probe.html")))
        if not measured:
            fail(f"{where}: the width probe did not run")
        elif int(measured.group(2)) > int(measured.group(1)):
            fail(f"{where}: the page overflows at 1400 px: {measured.group(2)} px wide in a {measured.group(1)} px window")
    print(f"checked {where}: {len(dom.links)} links, {len(dom.ids)} ids, {len(report['claims'])} claims, "
          f"{dom.rendered} TeX rendered, {len(dom.tex_left)} left as code")

print(f"{len(directories)} reports checked, {failures} failures")
sys.exit(1 if failures else 0)

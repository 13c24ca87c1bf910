"""doc_blocks.py - rewrites generated blocks in the README and docs/.

A block is the text between <!-- bench:NAME --> and <!-- /bench:NAME -->. The
same block may stand in several files (the README's summary and the
benchmark page's): each copy gets the same text. A block found in none of the
files is an error, so a renamed marker cannot leave stale figures behind.
"""
import glob
import re
import sys

DEFAULT_DOCS = ["README.md"] + sorted(glob.glob("docs/*.md"))


def write_blocks(blocks, docs, tool):
    texts = {path: open(path).read() for path in docs}
    for name, body in blocks.items():
        pat = re.compile(r"(<!-- bench:%s -->\n)(?:.*?\n)?(<!-- /bench:%s -->)" % (name, name), re.S)
        hits = [path for path, text in texts.items() if pat.search(text)]
        if not hits:
            sys.exit("%s: no bench:%s block in %s" % (tool, name, " ".join(docs)))
        for path in hits:
            texts[path] = pat.sub(lambda m: m.group(1) + body + "\n" + m.group(2), texts[path])
    for path, text in texts.items():
        open(path, "w").write(text)

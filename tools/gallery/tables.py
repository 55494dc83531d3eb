"""Markdown tables lifted from the project's docs into the gallery, so that a figure is written in
one place (docs/benchmark.md, say) and the page shows the same. Only what the docs' tables use:
header, separator, rows; `code`, **bold** and [links](target) in cells and paragraphs."""
import html
import os
import re


def _cells(line):
    return [c.strip() for c in line.strip().strip("|").split("|")]


def _bold(text):
    """Escaped text with its **bold** runs (the figures that meet a target) as <strong>."""
    return re.sub(r"\*\*([^*]+)\*\*", r"<strong>\1</strong>", html.escape(text))


def _links(text):
    """Escaped text with its Markdown links [words](target) as HTML links (the targets are relative
    to docs/, where the page is too), and its bold."""
    parts = re.split(r"\[([^\]]*)\]\(([^)\s]*)\)", text)
    out = []
    for i in range(0, len(parts), 3):
        out.append(_bold(parts[i]))
        if i + 2 < len(parts):
            out.append('<a href="%s">%s</a>' % (html.escape(parts[i + 2], quote=True), html.escape(parts[i + 1])))
    return "".join(out)


def _inline(text):
    parts = re.split(r"`([^`]*)`", text)
    return "".join(_links(p) if i % 2 == 0 else "<code>%s</code>" % html.escape(p) for i, p in enumerate(parts))


def tables_under(root, path, heading):
    """[(the paragraph before the table, header cells, rows)] for every table between `heading` (a whole
    Markdown heading line, "## Against POV-Ray") and the next heading of the same level."""
    with open(os.path.join(root, path)) as f:
        lines = f.read().splitlines()
    if heading not in lines:
        raise SystemExit("gallery: %s has no heading %r" % (path, heading))
    level = len(heading.split(" ")[0])
    start = lines.index(heading) + 1

    def ends(line):  # a heading of the same level or above
        marks = len(line) - len(line.lstrip("#"))
        return 0 < marks <= level and line[marks:marks + 1] == " "
    end = next((i for i in range(start, len(lines)) if ends(lines[i])), len(lines))
    out, i = [], start
    while i < end:
        if lines[i].startswith("|") and i + 1 < end and set(lines[i + 1].replace("|", "").strip()) <= set("-: "):
            # The paragraph just above the table says what it holds.
            k = i - 1
            while k >= start and not lines[k].strip():
                k -= 1
            paragraph = []
            while k >= start and lines[k].strip() and not lines[k].startswith(("|", "#", "```")):
                paragraph.insert(0, lines[k].strip())
                k -= 1
            lead = " ".join(paragraph)
            header, rows, i = _cells(lines[i]), [], i + 2
            while i < end and lines[i].startswith("|"):
                rows.append(_cells(lines[i]))
                i += 1
            out.append((lead, header, rows))
        else:
            i += 1
    return out


def tables_html(root, path, heading, count=None):
    """The first `count` tables under the heading (all of them: None), each with its paragraph."""
    out = []
    for lead, header, rows in tables_under(root, path, heading)[:count]:
        out.append('<p class="table-lead">%s</p>' % _inline(lead.rstrip(":")))
        out.append('<div class="table"><table><thead><tr>%s</tr></thead><tbody>%s</tbody></table></div>' % (
            "".join("<th>%s</th>" % _inline(h) for h in header),
            "".join("<tr>%s</tr>" % "".join("<td>%s</td>" % _inline(c) for c in row) for row in rows)))
    return "\n".join(out)

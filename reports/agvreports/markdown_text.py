"""Any string (a planner's label, a sweep's name) written into summary.md or CLAIMS.md so that
GitHub-flavoured Markdown shows it as it is: in a code span, or as plain text, in a table cell
or outside one. No label's '<' or '&' reaches the file as it is: Markdown renderers pass HTML
through, and not every one honours a backslash before '<' (Python-Markdown does not), while every
one decodes &lt; and &amp;. Standard library only.
"""

import re

LINE_BREAK = re.compile(r"\r\n|\r|\n")
# A line break inside a table row would end the row; a paragraph would fold it into a space.
BREAK = "<br>"
# What GFM could read as markup in the middle of a line: escapes, code, emphasis, raw HTML and
# entities, strikethrough, GitHub's $math$, table pipes, a heading's closing '#', and a link's
# "](" (with no definitions in the file, a bracket is a link only there: an interval "[0.9, 1.1]"
# stays as it is). '_' only where it can start or end emphasis (GFM never reads it between two
# letters or digits: `hma_star` stays as it is).
PLAIN_SPECIAL = re.compile(r"[\\`*<&~$|#]|\](?=\()|_(?![^\W_])|(?<![^\W_])_")
EVERY_UNDERSCORE = re.compile(r"[\\`*<&~$|#_]|\](?=\()")
# What opens a tag or an entity, as entities ('>' alone opens neither); the rest of the markup
# backslash-escaped.
ENTITIES = {"<": "&lt;", "&": "&amp;"}
HTML_SPECIAL = re.compile(r"[<&]")


def _escape(match):
    c = match.group(0)
    return ENTITIES.get(c, "\\" + c)


def plain(text, every_underscore=False):
    """`text` as Markdown plain text: '<' and '&' as entities, the other markup characters
    backslash-escaped (a backslash before ASCII punctuation is always a literal in CommonMark,
    and GFM's tables take `\\|` as a pipe of the cell), line breaks as <br>."""
    special = EVERY_UNDERSCORE if every_underscore else PLAIN_SPECIAL
    lines = LINE_BREAK.split(str(text))
    return BREAK.join(special.sub(_escape, line) for line in lines)


def _span(text, in_table):
    if in_table:
        # GFM splits a row at every pipe not right after a backslash, code spans included, and
        # drops that backslash before the cell is read: `\|` is a pipe even inside a code span.
        text = text.replace("|", "\\|")
    longest = max((len(run) for run in re.findall(r"`+", text)), default=0)
    fence = "`" * (longest + 1)
    # CommonMark strips one space from each end of a span that has both (and is not all
    # spaces), and a backtick at an end would join the fence: pad those with a space.
    if text.startswith("`") or text.endswith("`") or \
            (text.startswith(" ") and text.endswith(" ") and text.strip(" ")):
        text = f" {text} "
    return f"{fence}{text}{fence}"


def code(text, in_table=False):
    """`text` as a code span (backslashes and markup are literal there), a longer fence when the
    text holds backticks; a line break closes the span and opens another after a <br>. A text
    holding '<' or '&' is a <code> element instead, its content escaped as plain text: inside
    a code span an entity would show as written, and the raw character would be a tag or an
    entity to a renderer that does not honour the span."""
    if HTML_SPECIAL.search(str(text)):
        return f"<code>{plain(text, every_underscore=True)}</code>"
    lines = LINE_BREAK.split(str(text))
    spans = [_span(line, in_table) if line else "" for line in lines]
    if not any(spans):  # an empty span would be two backticks of text
        return "` `"
    return BREAK.join(spans)

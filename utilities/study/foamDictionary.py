"""The subset of OpenFOAM dictionary syntax sphkit's cases use, for the study utility: `key value;`,
nested `{ }`, lists `( )`, strings, `//` and `/* */` comments. parse() returns nested dicts
whose leaves are token lists; set_entry() replaces one entry's value in the text, keeping every
other character (comments, layout) as the user wrote it."""
import re

_TOKEN = re.compile(r'\s+|//[^\n]*|/\*.*?\*/|"[^"]*"|[{}();]|[^\s{}();"]+', re.S)


class DictionaryError(Exception):
    pass


def _tokens(text, name):
    """(token, start, end) for every token, comments and blanks skipped."""
    result, position = [], 0
    while position < len(text):
        match = _TOKEN.match(text, position)
        if not match:
            raise DictionaryError("%s:%d: cannot read '%s'" % (name, text.count("\n", 0, position) + 1, text[position:position + 20]))
        token = match.group(0)
        if not (token.isspace() or token.startswith("//") or token.startswith("/*")):
            result.append((token, match.start(), match.end()))
        position = match.end()
    return result


class Entry:
    """One entry: its value (a dict for a sub-dictionary, else a token list) and where the value lies in the text."""

    def __init__(self, value, start, end, line):
        self.value, self.start, self.end, self.line = value, start, end, line


def parse(text, name="dictionary"):
    """Nested {keyword: Entry}; raises DictionaryError naming the line for a malformed text."""
    tokens = _tokens(text, name)
    line_of = lambda position: text.count("\n", 0, position) + 1

    def block(k, closing):
        entries = {}
        while k < len(tokens) and tokens[k][0] != closing:
            keyword, keyword_start, _ = tokens[k]
            if keyword in "{}();":
                raise DictionaryError("%s:%d: expected a keyword, found '%s'" % (name, line_of(keyword_start), keyword))
            if k + 1 >= len(tokens):
                raise DictionaryError("%s:%d: '%s' has no value" % (name, line_of(keyword_start), keyword))
            if tokens[k + 1][0] == "{":
                sub, k_end = block(k + 2, "}")
                entries[keyword.strip('"')] = Entry(sub, tokens[k + 1][1], tokens[k_end][2], line_of(keyword_start))
                k = k_end + 1
                continue
            values, depth, j = [], 0, k + 1
            while j < len(tokens) and not (tokens[j][0] == ";" and depth == 0):
                depth += {"(": 1, ")": -1, "{": 1, "}": -1}.get(tokens[j][0], 0)
                values.append(tokens[j][0])
                j += 1
            if j >= len(tokens):
                raise DictionaryError("%s:%d: entry '%s' does not end with ';'" % (name, line_of(keyword_start), keyword))
            entries[keyword.strip('"')] = Entry(values, tokens[k + 1][1], tokens[j][1], line_of(keyword_start))
            k = j + 1
        if closing != "" and k >= len(tokens):
            raise DictionaryError("%s: a '{' is not closed" % name)
        return entries, k

    entries, _ = block(0, "")
    return entries


def find(entries, path):
    """The Entry at a '/'-separated path, or None."""
    entry = None
    for keyword in path.split("/"):
        if not isinstance(entries, dict) or keyword not in entries:
            return None
        entry = entries[keyword]
        entries = entry.value
    return entry


def set_entry(text, path, value, name="dictionary"):
    """The text with the entry at `path` given `value` (a sub-dictionary's braces included, or a
    plain value without its ';')."""
    entry = find(parse(text, name), path)
    if entry is None:
        raise DictionaryError("%s has no entry '%s'" % (name, path))
    block_before, block_after = isinstance(entry.value, dict), value.lstrip().startswith("{")
    end = entry.end + 1 if block_after and not block_before else entry.end  # a block takes no ';'
    return text[:entry.start] + value + (";" if block_before and not block_after else "") + text[end:]


def words(entry):
    """A list entry's items as strings: `(a "b c" 1)` -> ['a', 'b c', '1']."""
    items = entry.value
    if items and items[0] == "(" and items[-1] == ")":
        items = items[1:-1]
    return [item.strip('"') for item in items]

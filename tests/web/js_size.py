#!/usr/bin/python3
"""The page's JavaScript in small parts: every function at most MAX_FUNCTION lines, every file at
most MAX_FILE lines (issue 40).

    /usr/bin/python3 tests/web/js_size.py [FILE_OR_FOLDER]...    (default: app/web/src)

Prints each function or file over its limit and exits 1, else prints the longest function and
exits 0. tests/web/test_web.py runs it (SourceSize), with a check that it does fail on a long
function.

A function is a `{ ... }` body that follows a parameter list `(...)` that is not an `if`, `for`,
`while`, `switch`, `catch` or `with` (function declarations and expressions, methods such as
`update() {`), or that follows `=>`; its length is from the line of its header's `(` (or of its
name, for `function name(`) to the line of its closing `}`, both counted, nested functions included.
Strings, template literals, comments and regular expressions are skipped when matching brackets.
"""
import os
import re
import sys

MAX_FUNCTION = 40
MAX_FILE = 400
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
NOT_FUNCTIONS = {"if", "for", "while", "switch", "catch", "with"}
# After these (the last significant character or word) a '/' starts a regular expression.
REGEX_AFTER_CHARS = set("(,=:[!&|?{};+-*%<>~^")
REGEX_AFTER_WORDS = {"return", "typeof", "case", "do", "else", "in", "of", "new", "delete", "void", "throw"}


def tokens(text):
    """(kind, index) of each bracket and arrow outside strings, comments and regexes."""
    i, n = 0, len(text)
    last = ""  # the last significant character, or word
    while i < n:
        c = text[i]
        if c in " \t\r\n":
            i += 1
            continue
        if text.startswith("//", i):
            i = text.find("\n", i)
            i = n if i < 0 else i
            continue
        if text.startswith("/*", i):
            j = text.find("*/", i + 2)
            i = n if j < 0 else j + 2
            continue
        if c in "'\"`":
            i = skip_string(text, i)
            last = "a"
            continue
        if c == "/" and (last == "" or last in REGEX_AFTER_CHARS or last in REGEX_AFTER_WORDS):
            i = skip_regex(text, i)
            last = "a"
            continue
        m = re.compile(r"[A-Za-z_$][\w$]*").match(text, i)
        if m:
            last = m.group(0)
            i = m.end()
            continue
        if text.startswith("=>", i):
            yield "=>", i
            last = ">"
            i += 2
            continue
        if c in "(){}[]":
            yield c, i
        last = c
        i += 1


def skip_string(text, i):
    quote, i = text[i], i + 1
    while i < len(text):
        if text[i] == "\\":
            i += 2
            continue
        if text[i] == quote:
            return i + 1
        if quote == "`" and text.startswith("${", i):
            depth, i = 1, i + 2
            while i < len(text) and depth:
                depth += {"{": 1, "}": -1}.get(text[i], 0)
                i += 1
            continue
        i += 1
    return i


def skip_regex(text, i):
    i, in_class = i + 1, False
    while i < len(text) and text[i] != "\n":
        c = text[i]
        if c == "\\":
            i += 2
            continue
        if c == "[":
            in_class = True
        elif c == "]":
            in_class = False
        elif c == "/" and not in_class:
            i += 1
            while i < len(text) and (text[i].isalnum()):
                i += 1  # flags
            return i
        i += 1
    return i


def functions(text):
    """(name, first line, last line) of every function body in text."""
    line_of = lambda at: text.count("\n", 0, at) + 1
    stack = []        # open brackets: (char, index, function start or None)
    last_close = None  # the last ')' closed: index of its '('
    previous = None   # the previous token's kind
    found = []
    for kind, at in tokens(text):
        if kind in "([":
            stack.append((kind, at, None))
        elif kind == ")":
            opened = stack.pop() if stack else ("(", at, None)
            last_close = opened[1]
        elif kind == "{":
            start = None
            if previous == "=>":
                start = arrow_start(text, at)
            elif previous == ")":
                start = header_start(text, last_close)
            stack.append(("{", at, start))
        elif kind == "}":
            opened = stack.pop() if stack else ("{", at, None)
            if opened[2] is not None:
                name, start = opened[2]
                found.append((name, line_of(start), line_of(at)))
        elif kind == "]" and stack:
            stack.pop()
        previous = kind
    return found


def header_start(text, paren):
    """(name, index) of the function whose parameter list opens at paren, or None (an if, a for ...)."""
    before = text[:paren].rstrip()
    m = re.search(r"([A-Za-z_$][\w$]*)$", before)
    word = m.group(1) if m else ""
    if word in NOT_FUNCTIONS:
        return None
    if not word or word == "function":
        return ("(anonymous function)", paren)
    f = re.search(r"\bfunction\s*\*?\s*" + re.escape(word) + r"$", before)
    return (word, f.start() if f else m.start())


def arrow_start(text, arrow_brace):
    """(name, index) of an arrow function whose body opens at arrow_brace."""
    at = text.rfind("=>", 0, arrow_brace)
    head = text[:at]
    m = re.search(r"(?:(?:const|let|var)\s+)?([A-Za-z_$][\w$]*)\s*[=:]\s*(?:async\s*)?(?:\([^()]*\)|[\w$]+)\s*$", head)
    return ((m.group(1) + " =>") if m else "(arrow)", at)


def check(paths):
    """(problems, longest function) over the .js files of paths."""
    files = []
    for p in paths:
        if os.path.isdir(p):
            files += sorted(os.path.join(p, f) for f in os.listdir(p) if f.endswith(".js"))
        else:
            files.append(p)
    problems, longest = [], None
    for path in files:
        with open(path, encoding="utf-8") as f:
            text = f.read()
        rel = os.path.relpath(path, ROOT)
        lines = text.count("\n") + (0 if text.endswith("\n") else 1)
        if lines > MAX_FILE:
            problems.append("%s: %d lines (at most %d a file)" % (rel, lines, MAX_FILE))
        for name, first, last in functions(text):
            length = last - first + 1
            if longest is None or length > longest[0]:
                longest = (length, "%s:%d %s" % (rel, first, name))
            if length > MAX_FUNCTION:
                problems.append("%s:%d: %s is %d lines (at most %d a function)" % (rel, first, name, length, MAX_FUNCTION))
    return problems, longest


def main():
    paths = sys.argv[1:] or [os.path.join(ROOT, "app", "web", "src")]
    problems, longest = check(paths)
    for p in problems:
        print("js_size: " + p)
    if longest:
        print("js_size: the longest function: %s, %d lines" % (longest[1], longest[0]))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

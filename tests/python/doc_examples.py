"""The documented command lines of every analysis (docs/cli.md and docs/models/*.md synopses),
reduced to a runnable invocation: optional [groups] dropped, the first of (a | b) alternatives and
of a|b|c choices taken, placeholders (FILE, …, <...>) refused. Each is returned as (command path,
[(flag, value or None)])."""

import re
import shlex

from conftest import SOURCE


def _commands(text):
    for block in re.findall(r"```[a-z]*\n(.*?)```", text, flags=re.S):
        joined = re.sub(r"\\\n\s*", " ", block)
        for line in joined.splitlines():
            line = line.strip()
            if line.startswith("catena "):
                yield line
    for span in re.findall(r"`(catena [^`]*)`", text):  # an inline synopsis over several lines
        yield " ".join(span.split())


def _reduce(line):
    # '...' and '…' outside brackets, <placeholders>: not runnable
    tokens = shlex.split(line.replace("(", " ( ").replace(")", " ) ").replace("[", " [ ")
                         .replace("]", " ] "))
    out, depth, alt_skip = [], 0, False
    for t in tokens:
        if t == "[":
            depth += 1
            continue
        if t == "]":
            depth -= 1
            continue
        if depth:
            continue
        if t == "(":
            alt_skip = False
            continue
        if t == ")":
            alt_skip = False
            continue
        if t == "|":
            alt_skip = True
            continue
        if alt_skip:
            continue
        out.append(t)
    return out


def documented_examples(analyses):
    by_command = {tuple(a["command"]): a for a in analyses}
    seen = set()
    texts = [(SOURCE / "docs" / "cli.md").read_text()]
    texts += [p.read_text() for p in sorted((SOURCE / "docs" / "models").glob("*.md"))]
    for text in texts:
        for line in _commands(text):
            tokens = _reduce(line)[1:]
            path = []
            while tokens and not tokens[0].startswith("-") and tuple(path + [tokens[0]]) in \
                    {k[:len(path) + 1] for k in by_command}:
                path.append(tokens.pop(0))
            a = by_command.get(tuple(path))
            if a is None or any(("…" in t or "<" in t or t == "..." or t == "FILE")
                                for t in tokens):
                continue
            flags = []
            i = 0
            while i < len(tokens):
                flag = tokens[i]
                if not flag.startswith("--"):
                    break
                if i + 1 < len(tokens) and not tokens[i + 1].startswith("--"):
                    value = tokens[i + 1].split("|")[0]
                    i += 2
                else:
                    value = None
                    i += 1
                flags.append((flag, value))
            else:
                if any(f in ("--format", "--output", "--csv", "--svg", "--dxf") for f, _ in flags):
                    flags = [(f, v) for f, v in flags
                             if f not in ("--format", "--output", "--csv", "--svg", "--dxf")]
                key = (a["name"], tuple(flags))
                if flags and key not in seen:  # no flags: the command only named in prose
                    seen.add(key)
                    yield a, flags

"""The range of every numeric config key, as the loader enforces it, into docs/config.md's
"Limits" table (between its generated markers). Each key is probed with values far outside any
range; the refusal names the range (each options struct's IsValid). `--check` compares instead
of writing (python/tests/test_docs.py runs it). Needs the module: PYTHONPATH=build/python."""
import re
import sys
from pathlib import Path

import yaml

import anchorbench as ab

DOC = Path(__file__).resolve().parent.parent / "docs" / "config.md"
BEGIN, END = "<!-- generated: config_limits (scripts/config_limits.py) -->", "<!-- end generated -->"
BASE = {"navigation": {}, "exploration": {}, "pdop_study": {}}


def numeric_keys():
    def leaves(d, prefix=""):
        for key, value in d.items():
            if isinstance(value, dict):
                yield from leaves(value, f"{prefix}{key}.")
            elif isinstance(value, (int, float)) and not isinstance(value, bool):
                yield f"{prefix}{key}", value

    return list(leaves(yaml.safe_load(ab.load_config(BASE).yaml)))


def limit(key, default):
    """What the loader says of values far out: both signs (the largest whole numbers for an
    integer key), and a fraction for an integer key."""
    probes = ("2147483647", "-2147483647", "0.5") if isinstance(default, int) else ("1e300", "-1e300")
    said = []
    for value in probes:
        try:
            ab.load_config(BASE, overrides=[f"{key}={value}"])
        except ab.InputError as error:
            text = re.sub(r"^.*?key '[^']*': ", "", str(error))  # the file and key path
            text = re.sub(r", got .*$", "", text)
            if text not in said:
                said.append(text)
    return "; ".join(said) or "-"


def table():
    rows = ["| key | default | what a value outside it gets |", "|---|---|---|"]
    for key, default in numeric_keys():
        if key == "seed":
            continue
        rows.append(f"| `{key}` | {default} | {limit(key, default).replace('|', '/')} |")
    return "\n".join(rows)


def main():
    text = DOC.read_text()
    start, end = text.index(BEGIN) + len(BEGIN), text.index(END, text.index(BEGIN))
    updated = text[:start] + "\n" + table() + "\n" + text[end:]
    if "--check" in sys.argv:
        if updated != text:
            sys.exit("docs/config.md: the Limits table differs from what the loader enforces: run "
                     "PYTHONPATH=build/python /usr/bin/python3 scripts/config_limits.py")
        return
    DOC.write_text(updated)


if __name__ == "__main__":
    main()

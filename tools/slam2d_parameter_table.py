#!/usr/bin/env python3
"""The parameter table of docs/SLAM.md, from the library's declaration of Slam2DConfig
(metricmap.slam2d_parameters()). `--write` puts it into docs/SLAM.md between the
slam2d-parameters markers; python/tests/test_config_schema.py checks that the page holds it."""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
DOC = ROOT / "docs" / "SLAM.md"
MARK = re.compile(r"(<!-- slam2d-parameters -->\n)(.*?)(<!-- /slam2d-parameters -->)", re.S)


def table(parameters):
    rows = ["| name | kind | unit | range | default | meaning |", "|---|---|---|---|---|---|"]
    for p in parameters:
        rows.append(
            f"| `{p['name']}` | {p['kind']} | {p['unit'] or '—'} | {p['rule']} | "
            f"{p['default']} | {p['doc']} |"
        )
    return "\n".join(rows) + "\n"


def documented(text):
    m = MARK.search(text)
    return m.group(2) if m else None


def main():
    import metricmap as mm

    text = table(mm.slam2d_parameters())
    if "--write" in sys.argv:
        page = DOC.read_text()
        DOC.write_text(MARK.sub(lambda m: m.group(1) + text + m.group(3), page))
    else:
        sys.stdout.write(text)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""The parameter tables of the docs, from the library's declarations (metricmap.slam2d_parameters(),
localize2d_parameters(), slam3d_parameters()). `--write` puts each into its page between its
markers (<!-- NAME-parameters --> ... <!-- /NAME-parameters -->); python/tests/test_config_schema.py
checks that the pages hold them."""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
# declaration -> page
PAGES = {
    "slam2d": ROOT / "docs" / "SLAM.md",
    "localize2d": ROOT / "docs" / "LOCALIZATION.md",
    "slam3d": ROOT / "docs" / "SLAM3D.md",
}


def marker(name):
    return re.compile(rf"(<!-- {name}-parameters -->\n)(.*?)(<!-- /{name}-parameters -->)", re.S)


def table(parameters):
    rows = ["| name | kind | unit | range | default | meaning |", "|---|---|---|---|---|---|"]
    for p in parameters:
        rows.append(
            f"| `{p['name']}` | {p['kind']} | {p['unit'] or '—'} | {p['rule']} | "
            f"{p['default']} | {p['doc']} |"
        )
    return "\n".join(rows) + "\n"


def declared(name):
    import metricmap as mm

    return getattr(mm, f"{name}_parameters")()


def documented(name, text):
    m = marker(name).search(text)
    return m.group(2) if m else None


def main():
    for name, page in PAGES.items():
        text = table(declared(name))
        if "--write" in sys.argv:
            page.write_text(marker(name).sub(lambda m: m.group(1) + text + m.group(3), page.read_text()))
        else:
            sys.stdout.write(f"{page.name}:\n{text}\n")


if __name__ == "__main__":
    main()

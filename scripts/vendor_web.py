#!/usr/bin/env python3
"""Refresh the studio's vendored web parts (Blockly, CodeMirror) from npm at pinned versions.

The studio works offline: the page loads only files the package ships. This script is the one
way those files get into the repo: `npm pack` each package at its pinned version, copy the few
files the studio uses into rootlang/studio/static/vendor/<name>/, and write a VERSIONS note.

    python3 scripts/vendor_web.py          # refresh every vendored package
    python3 scripts/vendor_web.py --check  # exit 1 if the vendored files differ from npm's

Needs `npm` (it only downloads package tarballs; nothing is built or installed).
"""

from __future__ import annotations

import argparse
import filecmp
import shutil
import subprocess
import sys
import tarfile
import tempfile
from dataclasses import dataclass
from pathlib import Path

VENDOR_DIR = Path(__file__).resolve().parent.parent / "rootlang" / "studio" / "static" / "vendor"

# The languages the studio offers (Blockly's own messages; the rest of the page is ours).
BLOCKLY_LANGUAGES = ("en", "nl", "es", "fr", "de")


@dataclass(frozen=True)
class VendoredPackage:
    name: str  # npm package name, also the folder under vendor/
    version: str  # exact pin
    licence: str
    files: tuple[str, ...]  # paths inside the tarball's package/ folder; a trailing / copies a dir


PACKAGES = (
    VendoredPackage(
        name="blockly",
        version="13.3.0",
        licence="Apache-2.0",
        files=(
            "LICENSE",
            "blockly_compressed.js",
            "blocks_compressed.js",
            "media/",
            *(f"msg/{language}.js" for language in BLOCKLY_LANGUAGES),
        ),
    ),
    VendoredPackage(
        name="codemirror",
        version="5.65.21",
        licence="MIT",
        files=(
            "LICENSE",
            "lib/codemirror.js",
            "lib/codemirror.css",
            "addon/mode/simple.js",  # syntax colouring from a table of regular expressions
            "addon/edit/matchbrackets.js",
            "addon/selection/active-line.js",
        ),
    ),
)


def npm_pack(package: VendoredPackage, into: Path) -> Path:
    """Download the package's tarball (no install, no scripts) and unpack it; return package/."""
    result = subprocess.run(
        ["npm", "pack", "--silent", f"{package.name}@{package.version}"],
        cwd=into,
        check=True,
        capture_output=True,
        text=True,
    )
    tarball = into / result.stdout.strip().splitlines()[-1]
    with tarfile.open(tarball) as archive:
        archive.extractall(into / package.name, filter="data")
    return into / package.name / "package"


def copy_files(package: VendoredPackage, unpacked: Path, target: Path) -> None:
    if target.exists():
        shutil.rmtree(target)
    for wanted in package.files:
        source = unpacked / wanted.rstrip("/")
        destination = target / wanted.rstrip("/")
        destination.parent.mkdir(parents=True, exist_ok=True)
        if wanted.endswith("/"):
            shutil.copytree(source, destination)
        else:
            shutil.copy2(source, destination)


def versions_note() -> str:
    lines = [
        "# Vendored web parts",
        "",
        "Written by scripts/vendor_web.py (do not edit by hand; change the pins there and rerun).",
        "The studio page loads these from the studio's own address: no CDN, works offline.",
        "",
    ]
    for package in PACKAGES:
        lines.append(f"- {package.name} {package.version} ({package.licence}), from npm:")
        lines.extend(f"  - {wanted}" for wanted in package.files)
    return "\n".join(lines) + "\n"


def differences(expected: Path, actual: Path) -> list[str]:
    comparison = filecmp.dircmp(expected, actual)
    found: list[str] = []

    def walk(node: filecmp.dircmp[str], prefix: str) -> None:
        found.extend(prefix + name for name in node.left_only + node.right_only + node.diff_files)
        for name, child in node.subdirs.items():
            walk(child, f"{prefix}{name}/")

    walk(comparison, "")
    return found


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="compare only; change nothing")
    arguments = parser.parse_args(argv)
    with tempfile.TemporaryDirectory() as scratch_name:
        scratch = Path(scratch_name)
        fresh = scratch / "vendor"
        for package in PACKAGES:
            copy_files(package, npm_pack(package, scratch), fresh / package.name)
        (fresh / "VERSIONS.md").write_text(versions_note(), encoding="utf-8")
        if arguments.check:
            changed = differences(fresh, VENDOR_DIR) if VENDOR_DIR.exists() else ["(missing)"]
            for name in changed:
                print(f"differs: {name}")
            return 1 if changed else 0
        if VENDOR_DIR.exists():
            shutil.rmtree(VENDOR_DIR)
        shutil.copytree(fresh, VENDOR_DIR)
    for package in PACKAGES:
        print(f"vendored {package.name} {package.version} into {VENDOR_DIR / package.name}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

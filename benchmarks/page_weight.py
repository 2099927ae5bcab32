"""What the studio's page costs the school's Wi-Fi: the bytes of a first and a second load.

Run: ``.venv/bin/python benchmarks/page_weight.py [--pupils 30]``.

Starts ``rootlang studio`` (a separate process, as a teacher would) on a free port over an
empty folder, and loads its page in headless Chromium (Debian's ``chromium``) with a fresh
cache: the first load. Then the page is opened again in the same browser (a pupil coming back
to it, or a second lesson): the second load. Bytes are what went over the network (Chromium's
``encodedDataLength``: headers and compressed bodies), counted by the DevTools protocol. It
prints both loads' bytes and requests, the largest responses, and what a class of ``--pupils``
pulls reloading at once.
"""

from __future__ import annotations

import argparse
import tempfile
from typing import Any

from playwright.sync_api import sync_playwright
from studio_process import served_studio  # (this folder's: the script's own is on sys.path)

CHROMIUM = "/usr/bin/chromium"


def load(page: Any, address: str) -> dict[str, int]:
    """Open the page until the studio is ready; each response's bytes over the network."""
    cdp = page.context.new_cdp_session(page)
    cdp.send("Network.enable")
    urls: dict[str, str] = {}
    sizes: dict[str, int] = {}
    cdp.on(
        "Network.requestWillBeSent", lambda e: urls.update({e["requestId"]: e["request"]["url"]})
    )
    cdp.on(
        "Network.loadingFinished",
        lambda e: sizes.update(
            {urls.get(e["requestId"], e["requestId"]): int(e["encodedDataLength"])}
        ),
    )
    page.goto(address, wait_until="load")
    page.wait_for_selector(".blocklySvg", timeout=60_000)
    page.wait_for_load_state("networkidle")
    cdp.detach()
    return sizes


def report(name: str, sizes: dict[str, int]) -> int:
    total = sum(sizes.values())
    print(f"{name}: {total / 1000:,.0f} kB in {len(sizes)} responses")
    for url, size in sorted(sizes.items(), key=lambda item: -item[1])[:5]:
        print(f"    {size / 1000:8,.1f} kB  {url.split('/', 3)[-1]}")
    return total


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pupils", type=int, default=30)
    arguments = parser.parse_args()
    with (
        tempfile.TemporaryDirectory() as folder,
        served_studio(folder) as (address, _),
        sync_playwright() as driver,
    ):
        browser = driver.chromium.launch(
            executable_path=CHROMIUM, args=["--headless", "--no-sandbox", "--disable-gpu"]
        )
        page = browser.new_context().new_page()
        first = report("first load", load(page, address))
        second = report("second load", load(page, address))
        browser.close()
    print(
        f"a class of {arguments.pupils} reloading: {arguments.pupils * second / 1e6:.2f} MB "
        f"(first visit {arguments.pupils * first / 1e6:.1f} MB)"
    )


if __name__ == "__main__":
    main()

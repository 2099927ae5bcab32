"""`rootlang studio --https`: the certificate rootlang makes for this computer's LAN names (a
CA of its own, kept, and a server certificate signed by it), and the studio served over TLS to
a client that trusts only that CA."""

from __future__ import annotations

import asyncio
import base64
import hashlib
import ssl
import stat
from pathlib import Path

import aiohttp
from cryptography import x509
from cryptography.hazmat.primitives import serialization

from rootlang.studio.tls import lan_names, studio_certificate

from .conftest import RunningStudio


def leaf_of(path: Path) -> x509.Certificate:
    return x509.load_pem_x509_certificates(path.read_bytes())[0]


def test_the_certificate_names_this_computer_and_keeps_its_key(tmp_path: Path) -> None:
    made = studio_certificate("10.9.8.7", tmp_path)
    leaf = leaf_of(made.certificate)
    named = leaf.extensions.get_extension_for_class(x509.SubjectAlternativeName).value
    addresses = {str(a) for a in named.get_values_for_type(x509.IPAddress)}
    assert {"127.0.0.1", "10.9.8.7"} <= addresses
    assert "localhost" in named.get_values_for_type(x509.DNSName)
    spki = leaf.public_key().public_bytes(
        serialization.Encoding.DER, serialization.PublicFormat.SubjectPublicKeyInfo
    )
    assert made.spki_sha256 == base64.b64encode(hashlib.sha256(spki).digest()).decode()
    for key in (made.key, tmp_path / "ca.key"):
        assert stat.S_IMODE(key.stat().st_mode) == 0o600, "a private key only its owner reads"
    authority = made.authority.read_bytes()
    kept = made.certificate.read_bytes()
    assert studio_certificate("10.9.8.7", tmp_path).certificate.read_bytes() == kept
    moved = studio_certificate("10.9.8.99", tmp_path)  # a new address: made again...
    assert moved.certificate.read_bytes() != kept
    assert moved.spki_sha256 == made.spki_sha256  # ... with the same key
    assert moved.authority.read_bytes() == authority  # and the same CA the devices trust


def test_lan_names_lead_with_the_loopback_names() -> None:
    names = lan_names("192.168.5.5")
    assert names[:3] == ("localhost", "127.0.0.1", "::1") and "192.168.5.5" in names
    assert "0.0.0.0" not in lan_names("0.0.0.0")


def test_the_studio_serves_https_to_a_client_trusting_its_ca(
    class_folder: Path, tmp_path: Path
) -> None:
    made = studio_certificate("", tmp_path / "tls")
    studio = RunningStudio(class_folder, tls=made).start()
    try:
        assert studio.address.startswith("https://127.0.0.1:")
        trusting = ssl.create_default_context(cafile=str(made.authority))

        async def main() -> None:
            async with aiohttp.ClientSession(studio.address) as session:
                reply = await session.get("/api/setup", ssl=trusting)
                assert reply.status == 200
                setup = await reply.json()
                assert "square.root" in [p["name"] for p in setup["programs"]]
                socket = await session.ws_connect("/ws", ssl=trusting, origin=studio.address)
                await socket.close()

        asyncio.run(main())
    finally:
        studio.stop()

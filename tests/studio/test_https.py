"""`rootlang studio --https`: the certificate rootlang makes for this computer's LAN names (a
CA of its own, kept, and a server certificate signed by it), and the studio served over TLS to
a client that trusts only that CA."""

from __future__ import annotations

import asyncio
import base64
import datetime
import hashlib
import ipaddress
import ssl
import stat
from ipaddress import IPv4Network, IPv6Network
from pathlib import Path

import aiohttp
import pytest
from cryptography import x509
from cryptography.hazmat.primitives import hashes, serialization
from cryptography.hazmat.primitives.asymmetric import ec
from cryptography.x509 import DNSName, IPAddress
from cryptography.x509.verification import PolicyBuilder, Store, VerificationError

from rootlang.studio.tls import (
    CA_DAYS,
    StudioCertificate,
    lan_names,
    make_authority,
    sign_server_certificate,
    studio_certificate,
)

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
    assert stat.S_IMODE(made.key.stat().st_mode) == 0o600, "a private key only its owner reads"
    assert made.made_now
    authority = made.authority.read_bytes()
    kept = made.certificate.read_bytes()
    again = studio_certificate("10.9.8.7", tmp_path)
    assert again.certificate.read_bytes() == kept and not again.made_now
    moved = studio_certificate("10.9.8.99", tmp_path)  # a new address: made again...
    assert moved.certificate.read_bytes() != kept and moved.made_now
    assert moved.spki_sha256 == made.spki_sha256  # ... with the same key
    # ... and a new authority: the old one can't vouch for the new address
    assert moved.authority.read_bytes() != authority
    assert "10.9.8.99" in permitted(authority_of(moved))


def authority_of(made: StudioCertificate) -> x509.Certificate:
    return x509.load_pem_x509_certificate(made.authority.read_bytes())


def permitted(ca: x509.Certificate) -> set[str]:
    """The names the authority may vouch for (an address as a one-address network's address)."""
    constraints = ca.extensions.get_extension_for_class(x509.NameConstraints).value
    found: set[str] = set()
    for name in constraints.permitted_subtrees or ():
        if isinstance(name, x509.IPAddress):
            assert isinstance(name.value, (IPv4Network, IPv6Network))
            assert name.value.num_addresses == 1, "one address, not a network"
            found.add(str(name.value.network_address))
        else:
            found.add(str(name.value))
    return found


def test_the_authority_vouches_only_for_this_computer_for_a_term_and_keeps_no_key(
    tmp_path: Path,
) -> None:
    """The authority a school installs is name-constrained (critical) to exactly the studio's
    names and addresses, lasts a term, and its key is nowhere on disk."""
    made = studio_certificate("10.9.8.7", tmp_path)
    ca = authority_of(made)
    extension = ca.extensions.get_extension_for_class(x509.NameConstraints)
    assert extension.critical
    assert extension.value.excluded_subtrees is None
    assert permitted(ca) == {
        str(ipaddress.ip_address(name)) if ":" in name or name[0].isdigit() else name
        for name in made.names
    }
    assert {"localhost", "127.0.0.1", "::1", "10.9.8.7"} <= permitted(ca)
    assert "." in "".join(made.names)  # (a bare host name is left out: it could be a TLD)
    assert all("." in n or ":" in n or n == "localhost" for n in permitted(ca))
    lasts = ca.not_valid_after_utc - ca.not_valid_before_utc
    assert lasts <= datetime.timedelta(days=CA_DAYS + 1) <= datetime.timedelta(days=122)
    assert leaf_of(made.certificate).not_valid_after_utc <= ca.not_valid_after_utc
    # no private key but the server's own: the authority's is forgotten once it has signed
    keys = [p.name for p in tmp_path.iterdir() if b"PRIVATE KEY" in p.read_bytes()]
    assert keys == ["studio.key"]
    # the kept certificate verifies against it, as a browser would check it
    verifier = PolicyBuilder().store(Store([ca])).build_server_verifier(DNSName("localhost"))
    chain = x509.load_pem_x509_certificates(made.certificate.read_bytes())
    verifier.verify(chain[0], chain[1:])


def test_a_certificate_for_another_site_fails_against_the_authority() -> None:
    """Even signed with the authority's own key (which rootlang never keeps), a certificate for
    any name or address it was not made for is refused by a verifier that honours X.509 name
    constraints."""
    names = ("localhost", "127.0.0.1", "studio.school.lan", "10.9.8.7")
    now = datetime.datetime.now(datetime.timezone.utc)
    ca, ca_key = make_authority(names, now)
    server_key = ec.generate_private_key(ec.SECP256R1()).public_key()
    store = Store([ca])

    def verify(certified: tuple[str, ...], asked: DNSName | IPAddress) -> None:
        leaf = sign_server_certificate(ca, ca_key, server_key, certified)
        PolicyBuilder().store(store).time(now).build_server_verifier(asked).verify(leaf, [])

    verify(("studio.school.lan",), DNSName("studio.school.lan"))  # its own: good
    verify(("10.9.8.7",), IPAddress(ipaddress.ip_address("10.9.8.7")))
    for other, asked in (
        (("www.google.com",), DNSName("www.google.com")),
        (("studio.school.lan", "accounts.google.com"), DNSName("studio.school.lan")),
        (("school.lan",), DNSName("school.lan")),
        (("10.9.8.8",), IPAddress(ipaddress.ip_address("10.9.8.8"))),
        (("8.8.8.8",), IPAddress(ipaddress.ip_address("8.8.8.8"))),
    ):
        with pytest.raises(VerificationError):
            verify(other, asked)


def test_an_expired_or_old_style_authority_is_made_again_cleanly(tmp_path: Path) -> None:
    """An authority from an older rootlang (no name constraints, ten years, its key kept) or
    one near its end is replaced: a new authority and certificate, the old key deleted."""
    made = studio_certificate("10.9.8.7", tmp_path)
    now = datetime.datetime.now(datetime.timezone.utc)
    ca, ca_key = make_authority(made.names, now - datetime.timedelta(days=CA_DAYS))
    key = serialization.load_pem_private_key(made.key.read_bytes(), None)
    assert isinstance(key, ec.EllipticCurvePrivateKey)
    leaf = sign_server_certificate(ca, ca_key, key.public_key(), made.names)
    pem = serialization.Encoding.PEM
    made.authority.write_bytes(ca.public_bytes(pem))
    made.certificate.write_bytes(leaf.public_bytes(pem) + ca.public_bytes(pem))
    (tmp_path / "ca.key").write_bytes(b"-----BEGIN PRIVATE KEY-----\n")  # an older rootlang's
    renewed = studio_certificate("10.9.8.7", tmp_path)
    assert renewed.made_now and renewed.expires > now + datetime.timedelta(days=CA_DAYS - 1)
    assert authority_of(renewed).not_valid_after_utc == renewed.expires
    assert not (tmp_path / "ca.key").exists()
    unconstrained = (
        x509.CertificateBuilder().subject_name(ca.subject).issuer_name(ca.subject)
        .public_key(ca_key.public_key()).serial_number(1)
        .not_valid_before(now).not_valid_after(now + datetime.timedelta(days=3650))
        .add_extension(x509.BasicConstraints(ca=True, path_length=0), critical=True)
        .sign(ca_key, hashes.SHA256())
    )  # fmt: skip
    made.authority.write_bytes(unconstrained.public_bytes(pem))
    leaf = sign_server_certificate(unconstrained, ca_key, key.public_key(), made.names)
    made.certificate.write_bytes(leaf.public_bytes(pem) + unconstrained.public_bytes(pem))
    assert studio_certificate("10.9.8.7", tmp_path).made_now
    assert permitted(authority_of(renewed))


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

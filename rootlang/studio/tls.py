"""`rootlang studio --https`: a certificate for this computer's names and addresses on the LAN.

Web Bluetooth exists only in a secure context, so a pupil's Chromebook that opens
``http://<teacher's computer>:8765`` has no ``navigator.bluetooth`` at all. With ``--https``
the studio serves TLS with a certificate rootlang makes and keeps in the user's config folder
(:func:`config_folder`):

- ``ca.pem``: a small certificate authority of this computer's own ("rootlang studio on NAME"),
  the one file a school installs on pupils' devices (by policy on managed Chromebooks). It is
  **name-constrained** (X.509 NameConstraints, critical): it can vouch only for the names and
  addresses this computer had when it was made, so a device that trusts it trusts nothing else
  through it. It lasts :data:`CA_DAYS` (a school term), and its private key is **never kept**:
  it exists only in memory while the server's certificate is signed, so nobody can copy it
  from this computer, nor from a pupil's (they get ``ca.pem`` only);
- ``studio.pem`` / ``studio.key``: the server's certificate, signed by it, for those same names
  and addresses, valid as long as the authority (its key kept: its SPKI fingerprint, the one
  ``--ignore-certificate-errors-spki-list`` takes, stays the same).

Both are made again together — a new authority, which devices must be given again — when the
authority is about to expire (:data:`RENEW_DAYS` left) or this computer has a name or address
it does not cover. The private key is written readable by its owner only.
"""

from __future__ import annotations

import base64
import contextlib
import datetime
import hashlib
import ipaddress
import os
import socket
import ssl
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, cast

if TYPE_CHECKING:
    from cryptography import x509
    from cryptography.hazmat.primitives.asymmetric import ec

CA_DAYS = 100  # the class set's trust: a school term (about 14 weeks), then made again
RENEW_DAYS = 1  # made again when it has less than this left (never expiring mid-lesson)
WARN_DAYS = 14  # the start-up says when it must be installed again, from this long before


@dataclass(frozen=True)
class StudioCertificate:
    folder: Path
    names: tuple[str, ...]  # DNS names and IP addresses, as in the certificate
    spki_sha256: str  # base64, as Chrome's --ignore-certificate-errors-spki-list takes it
    expires: datetime.datetime  # when the authority and the certificate end (UTC)
    made_now: bool  # made (again) just now: a new ca.pem for the devices

    @property
    def certificate(self) -> Path:
        return self.folder / "studio.pem"

    @property
    def key(self) -> Path:
        return self.folder / "studio.key"

    @property
    def authority(self) -> Path:
        return self.folder / "ca.pem"

    @property
    def ending_soon(self) -> bool:
        """Whether it ends within :data:`WARN_DAYS` (the start-up says so)."""
        left = self.expires - datetime.datetime.now(datetime.timezone.utc)
        return left < datetime.timedelta(days=WARN_DAYS)

    def ssl_context(self) -> ssl.SSLContext:
        context = ssl.create_default_context(ssl.Purpose.CLIENT_AUTH)
        context.load_cert_chain(self.certificate, self.key)
        return context


def config_folder() -> Path:
    """rootlang's folder in the user's config folder (XDG on Linux, Application Support on
    macOS, %APPDATA% on Windows); ``ROOTLANG_CONFIG`` names another."""
    chosen = os.environ.get("ROOTLANG_CONFIG")
    if chosen:
        return Path(chosen)
    if sys.platform == "win32":
        return Path(os.environ.get("APPDATA", Path.home() / "AppData" / "Roaming")) / "rootlang"
    if sys.platform == "darwin":
        return Path.home() / "Library" / "Application Support" / "rootlang"
    return Path(os.environ.get("XDG_CONFIG_HOME") or Path.home() / ".config") / "rootlang"


def lan_names(host: str = "") -> tuple[str, ...]:
    """This computer's names and addresses a browser on the LAN may use: its host name (also
    with ``.local``, which mDNS answers), its fully qualified name, its IPv4 and IPv6 addresses,
    ``localhost`` and the loopback addresses, and ``host`` if it names one."""
    names: list[str] = ["localhost", "127.0.0.1", "::1"]
    hostname = socket.gethostname()
    for name in (hostname, f"{hostname.split('.')[0]}.local", socket.getfqdn()):
        names.append(name)
    with contextlib.suppress(OSError):
        for *_, address in socket.getaddrinfo(hostname, None):
            names.append(str(address[0]).split("%")[0])
    names.append(_routed_address())
    if host and host not in ("0.0.0.0", "::"):
        names.append(host)
    seen: dict[str, None] = {}
    for name in names:
        if name and name.lower() not in seen:
            seen[name.lower()] = None
    return tuple(seen)


def _routed_address() -> str:
    """The address this computer's default route leaves from (no packet is sent: a UDP socket
    only picks its source address when "connected")."""
    with contextlib.suppress(OSError), socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as probe:
        probe.connect(("192.0.2.1", 9))  # TEST-NET-1: never routed anywhere for real
        return str(probe.getsockname()[0])
    return ""


def certificate_names(host: str = "") -> tuple[str, ...]:
    """The names the certificate (and its authority's constraints) cover: :func:`lan_names`
    without a bare one-word host name (``localhost`` apart): a constraint permits a name and
    every name under it, and a computer called ``app`` or ``com`` must not make an authority
    for a whole top-level domain. Pupils reach it by ``NAME.local`` or its address."""
    return tuple(name for name in lan_names(host)
                 if "." in name or ":" in name or name.lower() == "localhost")  # fmt: skip


def studio_certificate(host: str = "", folder: Path | None = None) -> StudioCertificate:
    """The studio's certificate for this computer's names now, made (or made again, with a new
    authority) if needed."""
    from cryptography.hazmat.primitives import serialization
    from cryptography.hazmat.primitives.asymmetric import ec

    folder = folder or config_folder() / "studio-tls"
    folder.mkdir(parents=True, exist_ok=True)
    names = certificate_names(host)
    now = datetime.datetime.now(datetime.timezone.utc)
    with contextlib.suppress(FileNotFoundError):  # an authority's key an older rootlang kept
        (folder / "ca.key").unlink()
    key_path = folder / "studio.key"
    key: ec.EllipticCurvePrivateKey | None = None
    if key_path.exists():
        loaded = serialization.load_pem_private_key(key_path.read_bytes(), None)
        key = loaded if isinstance(loaded, ec.EllipticCurvePrivateKey) else None
    if key is None:
        key = ec.generate_private_key(ec.SECP256R1())
        _write_private(key_path, key.private_bytes(
            serialization.Encoding.PEM, serialization.PrivateFormat.PKCS8,
            serialization.NoEncryption(),
        ))  # fmt: skip
    spki = key.public_key().public_bytes(
        serialization.Encoding.DER, serialization.PublicFormat.SubjectPublicKeyInfo
    )
    fingerprint = base64.b64encode(hashlib.sha256(spki).digest()).decode()
    kept = _kept(folder, key, names, now)
    if kept is not None:
        return StudioCertificate(folder, names, fingerprint, kept, made_now=False)
    ca, ca_key = make_authority(names, now)
    leaf = sign_server_certificate(ca, ca_key, key.public_key(), names)
    del ca_key  # never written: nothing can sign for these names again
    pem = serialization.Encoding.PEM
    (folder / "studio.pem").write_bytes(leaf.public_bytes(pem) + ca.public_bytes(pem))
    (folder / "ca.pem").write_bytes(ca.public_bytes(pem))
    return StudioCertificate(folder, names, fingerprint, ca.not_valid_after_utc, made_now=True)


def _general_names(names: tuple[str, ...], *, networks: bool) -> list[x509.GeneralName]:
    """The names as X.509 general names: DNS names, and IP addresses (as one-address
    networks, ``networks``, for name constraints)."""
    from cryptography import x509

    made: list[x509.GeneralName] = []
    for name in names:
        if _is_ip(name):
            address = ipaddress.ip_address(name)
            made.append(x509.IPAddress(ipaddress.ip_network(address) if networks else address))
        else:
            made.append(x509.DNSName(name))
    return made


def make_authority(
    names: tuple[str, ...], now: datetime.datetime
) -> tuple[x509.Certificate, ec.EllipticCurvePrivateKey]:
    """A new authority for ``names`` only (NameConstraints, critical: exactly these DNS names
    and addresses), valid :data:`CA_DAYS` from ``now``, and its key (for the caller to sign
    with, then forget)."""
    from cryptography import x509
    from cryptography.hazmat.primitives import hashes
    from cryptography.hazmat.primitives.asymmetric import ec
    from cryptography.x509.oid import NameOID

    ca_key = ec.generate_private_key(ec.SECP256R1())
    subject = x509.Name([
        x509.NameAttribute(NameOID.COMMON_NAME, f"rootlang studio on {socket.gethostname()}"),
        x509.NameAttribute(NameOID.ORGANIZATION_NAME, "rootlang studio"),
    ])  # fmt: skip
    ca = (
        x509.CertificateBuilder().subject_name(subject).issuer_name(subject)
        .public_key(ca_key.public_key()).serial_number(x509.random_serial_number())
        .not_valid_before(now - datetime.timedelta(hours=1))
        .not_valid_after(now + datetime.timedelta(days=CA_DAYS))
        .add_extension(x509.BasicConstraints(ca=True, path_length=0), critical=True)
        .add_extension(x509.KeyUsage(
            digital_signature=False, key_cert_sign=True, crl_sign=True,
            content_commitment=False, key_encipherment=False, data_encipherment=False,
            key_agreement=False, encipher_only=False, decipher_only=False,
        ), critical=True)
        .add_extension(x509.NameConstraints(
            permitted_subtrees=_general_names(names, networks=True), excluded_subtrees=None,
        ), critical=True)
        .add_extension(x509.SubjectKeyIdentifier.from_public_key(ca_key.public_key()),
                       critical=False)
        .sign(ca_key, hashes.SHA256())
    )  # fmt: skip
    return ca, ca_key


def sign_server_certificate(
    ca: x509.Certificate,
    ca_key: ec.EllipticCurvePrivateKey,
    public_key: ec.EllipticCurvePublicKey,
    names: tuple[str, ...],
) -> x509.Certificate:
    """A server certificate for ``names``, signed by ``ca``, valid as long as it is."""
    from cryptography import x509
    from cryptography.hazmat.primitives import hashes
    from cryptography.x509.oid import ExtendedKeyUsageOID, NameOID

    own = [name for name in names if not _is_ip(name) and name.lower() != "localhost"]
    common_name = own[0] if own else names[0]  # the computer's own name
    return (
        x509.CertificateBuilder()
        .subject_name(x509.Name([x509.NameAttribute(NameOID.COMMON_NAME, common_name)]))
        .issuer_name(ca.subject).public_key(public_key)
        .serial_number(x509.random_serial_number())
        .not_valid_before(ca.not_valid_before_utc)
        .not_valid_after(ca.not_valid_after_utc)
        .add_extension(x509.SubjectAlternativeName(_general_names(names, networks=False)),
                       critical=False)
        .add_extension(x509.BasicConstraints(ca=False, path_length=None), critical=True)
        .add_extension(x509.KeyUsage(
            digital_signature=True, key_cert_sign=False, crl_sign=False,
            content_commitment=False, key_encipherment=False, data_encipherment=False,
            key_agreement=False, encipher_only=False, decipher_only=False,
        ), critical=True)
        .add_extension(x509.ExtendedKeyUsage([ExtendedKeyUsageOID.SERVER_AUTH]), critical=False)
        .add_extension(x509.AuthorityKeyIdentifier.from_issuer_public_key(
            cast("ec.EllipticCurvePublicKey", ca.public_key())), critical=False)
        .sign(ca_key, hashes.SHA256())
    )  # fmt: skip


def _kept(
    folder: Path, key: ec.EllipticCurvePrivateKey, names: tuple[str, ...], now: datetime.datetime
) -> datetime.datetime | None:
    """When the kept authority and certificate end, if they are still good: the authority
    name-constrained to (at least) every name now, with more than :data:`RENEW_DAYS` left, and
    the certificate its, for ``key``, naming them all. None: make them again."""
    from cryptography import x509
    from cryptography.exceptions import InvalidSignature

    try:
        ca = x509.load_pem_x509_certificate((folder / "ca.pem").read_bytes())
        leaf = x509.load_pem_x509_certificates((folder / "studio.pem").read_bytes())[0]
        constraints = ca.extensions.get_extension_for_class(x509.NameConstraints)
        named = leaf.extensions.get_extension_for_class(x509.SubjectAlternativeName).value
        leaf.verify_directly_issued_by(ca)
    except (OSError, ValueError, TypeError, x509.ExtensionNotFound, InvalidSignature):
        return None
    wanted = {_canonical(name) for name in names}
    permitted = {_canonical(str(getattr(n, "value", ""))) for n in
                 constraints.value.permitted_subtrees or ()}  # fmt: skip
    have = {_canonical(str(n.value)) for n in named}
    ends = min(ca.not_valid_after_utc, leaf.not_valid_after_utc)
    good = (constraints.critical and wanted <= permitted and wanted <= have
            and leaf.public_key() == key.public_key()
            and ends - now > datetime.timedelta(days=RENEW_DAYS))  # fmt: skip
    return ends if good else None


def _canonical(name: str) -> str:
    """A name as compared: an address (or a one-address network) as its address, a DNS name
    in lower case."""
    with contextlib.suppress(ValueError):
        network = ipaddress.ip_network(name)
        if network.num_addresses == 1:
            return str(network.network_address)
    return name.lower()


def _is_ip(name: str) -> bool:
    try:
        ipaddress.ip_address(name)
    except ValueError:
        return False
    return True


def _write_private(path: Path, data: bytes) -> None:
    """A private key, readable by its owner only (created so, never widened)."""
    descriptor = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)
    with os.fdopen(descriptor, "wb") as file:
        file.write(data)

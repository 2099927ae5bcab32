"""`rootlang studio --https`: a certificate for this computer's names and addresses on the LAN.

Web Bluetooth exists only in a secure context, so a pupil's Chromebook that opens
``http://<teacher's computer>:8765`` has no ``navigator.bluetooth`` at all. With ``--https``
the studio serves TLS with a certificate rootlang makes and keeps in the user's config folder
(:func:`config_folder`):

- ``ca.pem`` / ``ca.key``: a small certificate authority of this computer's own ("rootlang
  studio on NAME"), made once and kept: the one certificate a school installs on pupils'
  devices (by policy on managed Chromebooks), which then stays valid when the addresses change;
- ``studio.pem`` / ``studio.key``: the server's certificate, signed by it, for every name and
  address this computer has now (made again, with the same key, when they change: its SPKI
  fingerprint, the one ``--ignore-certificate-errors-spki-list`` takes, stays the same).

The private keys are written readable by their owner only.
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

CA_DAYS = 3650  # the class set's trust: installed once, for years
SERVER_DAYS = 397  # what browsers accept for a server certificate (398 days at most)
RENEW_DAYS = 30  # made again when it has less than this left


@dataclass(frozen=True)
class StudioCertificate:
    folder: Path
    names: tuple[str, ...]  # DNS names and IP addresses, as in the certificate
    spki_sha256: str  # base64, as Chrome's --ignore-certificate-errors-spki-list takes it

    @property
    def certificate(self) -> Path:
        return self.folder / "studio.pem"

    @property
    def key(self) -> Path:
        return self.folder / "studio.key"

    @property
    def authority(self) -> Path:
        return self.folder / "ca.pem"

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


def studio_certificate(host: str = "", folder: Path | None = None) -> StudioCertificate:
    """The studio's certificate for this computer's names now, made (or made again) if needed."""
    from cryptography import x509
    from cryptography.hazmat.primitives import hashes, serialization
    from cryptography.hazmat.primitives.asymmetric import ec
    from cryptography.x509.oid import ExtendedKeyUsageOID, NameOID

    folder = folder or config_folder() / "studio-tls"
    folder.mkdir(parents=True, exist_ok=True)
    names = lan_names(host)
    now = datetime.datetime.now(datetime.timezone.utc)

    def key_at(path: Path) -> ec.EllipticCurvePrivateKey:
        if path.exists():
            loaded = serialization.load_pem_private_key(path.read_bytes(), None)
            if isinstance(loaded, ec.EllipticCurvePrivateKey):
                return loaded
        made = ec.generate_private_key(ec.SECP256R1())
        _write_private(path, made.private_bytes(
            serialization.Encoding.PEM, serialization.PrivateFormat.PKCS8,
            serialization.NoEncryption(),
        ))  # fmt: skip
        return made

    ca_key = key_at(folder / "ca.key")
    ca_path = folder / "ca.pem"
    ca = x509.load_pem_x509_certificate(ca_path.read_bytes()) if ca_path.exists() else None
    if ca is None or ca.public_key() != ca_key.public_key() or ca.not_valid_after_utc < now:
        subject = x509.Name([
            x509.NameAttribute(NameOID.COMMON_NAME, f"rootlang studio on {socket.gethostname()}"),
            x509.NameAttribute(NameOID.ORGANIZATION_NAME, "rootlang studio"),
        ])  # fmt: skip
        ca = (
            x509.CertificateBuilder().subject_name(subject).issuer_name(subject)
            .public_key(ca_key.public_key()).serial_number(x509.random_serial_number())
            .not_valid_before(now - datetime.timedelta(days=1))
            .not_valid_after(now + datetime.timedelta(days=CA_DAYS))
            .add_extension(x509.BasicConstraints(ca=True, path_length=0), critical=True)
            .add_extension(x509.KeyUsage(
                digital_signature=True, key_cert_sign=True, crl_sign=True,
                content_commitment=False, key_encipherment=False, data_encipherment=False,
                key_agreement=False, encipher_only=False, decipher_only=False,
            ), critical=True)
            .add_extension(x509.SubjectKeyIdentifier.from_public_key(ca_key.public_key()),
                           critical=False)
            .sign(ca_key, hashes.SHA256())
        )  # fmt: skip
        ca_path.write_bytes(ca.public_bytes(serialization.Encoding.PEM))

    key = key_at(folder / "studio.key")
    spki = key.public_key().public_bytes(
        serialization.Encoding.DER, serialization.PublicFormat.SubjectPublicKeyInfo
    )
    made = StudioCertificate(
        folder, names, base64.b64encode(hashlib.sha256(spki).digest()).decode()
    )
    if _still_good(made, ca, now):
        return made
    alternatives: list[x509.GeneralName] = []
    for name in names:
        try:
            alternatives.append(x509.IPAddress(ipaddress.ip_address(name)))
        except ValueError:
            alternatives.append(x509.DNSName(name))
    common_name = names[3] if len(names) > 3 else names[0]  # the computer's own name
    leaf = (
        x509.CertificateBuilder()
        .subject_name(x509.Name([x509.NameAttribute(NameOID.COMMON_NAME, common_name)]))
        .issuer_name(ca.subject).public_key(key.public_key())
        .serial_number(x509.random_serial_number())
        .not_valid_before(now - datetime.timedelta(days=1))
        .not_valid_after(now + datetime.timedelta(days=SERVER_DAYS))
        .add_extension(x509.SubjectAlternativeName(alternatives), critical=False)
        .add_extension(x509.BasicConstraints(ca=False, path_length=None), critical=True)
        .add_extension(x509.ExtendedKeyUsage([ExtendedKeyUsageOID.SERVER_AUTH]), critical=False)
        .add_extension(x509.AuthorityKeyIdentifier.from_issuer_public_key(ca_key.public_key()),
                       critical=False)
        .sign(ca_key, hashes.SHA256())
    )  # fmt: skip
    made.certificate.write_bytes(
        leaf.public_bytes(serialization.Encoding.PEM) + ca.public_bytes(serialization.Encoding.PEM)
    )
    return made


def _still_good(made: StudioCertificate, ca: object, now: datetime.datetime) -> bool:
    """The kept certificate names every name now, has a month left, and is the CA's."""
    from cryptography import x509

    if not made.certificate.exists():
        return False
    try:
        leaf = x509.load_pem_x509_certificate(made.certificate.read_bytes())
        named = leaf.extensions.get_extension_for_class(x509.SubjectAlternativeName).value
    except (ValueError, x509.ExtensionNotFound):
        return False
    have = {str(n.value).lower() for n in named}
    have |= {str(ip) for ip in named.get_values_for_type(x509.IPAddress)}
    wanted = {str(ipaddress.ip_address(n)) if _is_ip(n) else n.lower() for n in made.names}
    left = leaf.not_valid_after_utc - now
    return (wanted <= have and left > datetime.timedelta(days=RENEW_DAYS)
            and isinstance(ca, x509.Certificate) and leaf.issuer == ca.subject)  # fmt: skip


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

"""The tamper-test helper shared by the certificate test modules.

Import with ``from certificate_checks import rejected`` (pytest puts ``tests/`` on the path).
"""

from __future__ import annotations

from exactsym import checker


def rejected(cert: dict, fragment: str = "") -> None:
    """The tampered certificate (its configuration digest renewed, so that the tampering
    itself is judged) fails the independent check with a message containing ``fragment``."""
    cert["configuration_sha256"] = checker.digest(cert["configuration"])
    ok, message = checker.verify_certificate(cert)
    assert not ok and fragment in message, message

"""Code the package no longer holds because input does not reach it, kept as oracles for
differential tests (issue 29)."""

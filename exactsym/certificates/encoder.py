"""The numbers of a certificate: the number field of a configuration written exactly.

Rationals are written ``"p/q"``.  Irrational numbers are written in a field Q(theta) with a
REAL generator, so that the checker can decide signs with rational intervals:

* square roots of rationals (the kernel's multiquadratic numbers): natively, ``{"radicands":
  [p, ...]}`` (the primes of the radicands) with elements ``{m: c}`` = sum c sqrt(m): no field
  embedding, so any number of distinct square roots certifies;
* a cyclotomic field Q(zeta_M) (trigonometry): its real elements lie in the real
  subfield Q(theta), theta = 2cos(2pi/M), whose minimal polynomial Psi_M is known in closed form
  (``"irreducible": {"method": "real-cyclotomic", "conductor": M}``).  A real
  x = sum c_k zeta^k equals (x + conj x)/2 = c_0 + sum_k c_k V_k(theta)/2 with
  V_k(theta) = zeta^k + zeta^-k (V_0 = 2, V_1 = theta, V_(k+1) = theta V_k - V_(k-1));
* a field built by sympy's primitive element (nested radicals): theta is already real; its
  irreducibility is shown by a prime modulo which the minimal polynomial stays irreducible
  (``{"method": "prime", "prime": p}``); a field without such a prime (Galois group with no
  deg-cycle) cannot be certified (:class:`CertificateError`);
* towers of square roots over these, and the sparse Q(zeta_N) (``{"sparse-cyclotomic": ...}``).

theta is located by an interval [lo, hi] holding no other root of its minimal polynomial.
The producer computes with python-flint only: it shares no function with the checker, which
re-checks every field description it is given.
"""

from __future__ import annotations

import math
from fractions import Fraction

from flint import arb, arb_poly, ctx, fmpq, fmpq_poly, fmpz, fmpz_poly, nmod_poly

from .fields import square_root_proof
from ..exact import FieldElement
from ..exact.multiquadratic import MQ
from ..exact.cyclotomic_tower import CyclotomicTower
from ..exact.evaluate import SparseCyclotomicSystem
from ..exact.sparse_cyclotomic import SparseCyclotomic
from ..exact.tower import TowerElement
from ..exact.sparse_tower import SparseKummerTower
from ..exact.tower_proof import (base_kummer_witness, cyclotomic_nonsquare_witness,
                                kummer_witness, legendre_rank_primes, nonsquare_witness)
from .primes import MR_LIMIT, PrimalityError, hashing_prime_factors, primality_proofs


class CertificateError(Exception):
    """This configuration cannot be certified (or a bug: the group is not the truth)."""


# ------------------------------------------------------------------ numbers

def rational_text(q) -> str:
    q = fmpq(q) if not isinstance(q, fmpq) else q
    return str(q.p) if q.q == 1 else f"{q.p}/{q.q}"


def _to_fmpq(q: Fraction) -> fmpq:
    return fmpq(q.numerator, q.denominator)


def _ball_bounds(ball) -> tuple[Fraction, Fraction]:
    """Rational lo <= hi with the whole ball inside [lo, hi]."""
    man, exp = ball.mid().man_exp()
    rman, rexp = ball.rad().man_exp()
    mid = Fraction(int(man)) * Fraction(2) ** int(exp)
    rad = Fraction(int(rman)) * Fraction(2) ** int(rexp)
    return mid - rad, mid + rad


def one_sign_change(minpoly: fmpq_poly, lo: Fraction, hi: Fraction) -> bool:
    """Descartes' rule of signs on q(x) = (1 + x)^d p(lo + (hi - lo)/(1 + x)), whose positive
    roots are the roots of p in (lo, hi): one sign change of q's coefficients means exactly one
    root there.  The test the checker applies to the interval (its own code, in integers);
    here with flint's polynomial composition, so the interval written is one it accepts."""
    q = minpoly(fmpq_poly([_to_fmpq(lo), _to_fmpq(hi - lo)])).coeffs()  # p(lo + (hi - lo) x)
    q = fmpq_poly(q[::-1])(fmpq_poly([1, 1]))               # x^d p(lo + (hi - lo)/x) at 1 + x
    signs = [c > 0 for c in q.coeffs() if c != 0]
    return sum(a != b for a, b in zip(signs, signs[1:])) == 1


def _isolating_interval(minpoly: list[Fraction], enclose) -> tuple[Fraction, Fraction]:
    """A short dyadic interval around theta (``enclose(prec)`` is an arb ball) holding no
    other root of ``minpoly``: the coarsest [floor(lo 2^k), ceil(hi 2^k)] / 2^k that does."""
    poly = fmpq_poly([_to_fmpq(c) for c in minpoly])
    prec = 64
    while prec <= 1 << 16:
        low, high = _ball_bounds(enclose(prec))
        for k in range(prec + 2):
            scale = 2 ** k
            lo = Fraction(math.floor(low * scale), scale)
            hi = Fraction(math.ceil(high * scale) + (1 if high * scale == math.ceil(high * scale)
                                                    else 0), scale)
            if poly(_to_fmpq(lo)) * poly(_to_fmpq(hi)) < 0 and one_sign_change(poly, lo, hi):
                return lo, hi
        prec *= 2
    raise CertificateError("could not isolate the generator of the number field")


class Encoder:
    """Writes the numbers of one number system in the certificate's exact form."""

    def __init__(self, system, values):
        field = getattr(system, "field", None)
        self.spec = self.radicands = self.tower = self.sparse = None
        if all(not isinstance(v, FieldElement) or v.is_rational() for v in values):
            self.field = None                   # everything is rational: no field at all
            return
        if isinstance(system, SparseCyclotomicSystem):
            self._sparse(system, values)        # Q(zeta_N) beyond a minimal polynomial
            return
        if any(isinstance(v, TowerElement) for v in values):
            self._tower(system.tower, values)   # nested radicals: a tower of quadratic fields
            return
        if field is None:                       # square roots of rationals (MQ elements):
            self._square_roots(values)          # written natively, no field embedding
            return
        self.field = field
        self.atoms = getattr(system, "atoms", None)
        if field.conductor is not None:
            self._cyclotomic(field)
        else:
            self._general(field)

    def _sparse(self, system, values):
        """``{"sparse-cyclotomic": {conductor, factors, prime, root[, primality]}}``
        (checker/ext_sparse.py): the checker proves the factors prime (Miller-Rabin, or above its
        range the ``primality`` proofs of prime_certificates), the prime l = 1 mod N and the
        root of order N mod l (its hash), and every denominator prime to l; numbers are
        {e: c} = sum c cos(2 pi e/N)."""
        self.field = None
        self.sparse = system.context
        self.spec = self._sparse_spec(system.context, values)

    def _sparse_spec(self, context, values) -> dict:
        """The ``{"sparse-cyclotomic": ...}`` field of :meth:`_sparse` (``values``: sparse
        numbers or rationals, whose denominators must be prime to l)."""
        ell = context.ell                       # l - 1 = k N: factored from N's factors
        known = {ell: hashing_prime_factors(ell, context.n, context.factors)} \
            if ell >= MR_LIMIT else {}
        try:
            proofs = primality_proofs([*context.factors, ell], known)
        except PrimalityError as err:
            raise CertificateError(f"Q(zeta_{context.n}): {err}") from None
        for v in values:
            if isinstance(v, SparseCyclotomic):
                coeffs = list(v.num.values()) + list((v.den or {}).values())
                if any(int(c.q) % context.ell == 0 for c in coeffs):
                    raise CertificateError("a denominator is divisible by the hashing prime")
            elif int(fmpq(v).q if not isinstance(v, FieldElement) else v.to_fmpq().q) \
                    % context.ell == 0:
                raise CertificateError("a denominator is divisible by the hashing prime")
        spec = {"sparse-cyclotomic": {
            "conductor": str(context.n),
            "factors": [[str(p), a] for p, a in sorted(context.factors.items())],
            "prime": str(context.ell), "root": str(context.g)}}
        if proofs:
            spec["sparse-cyclotomic"]["primality"] = proofs
        return spec

    def _sparse_tower(self, tower, values):
        """Square roots of rationals over the sparse Q(zeta_N) (checker/ext_sparse_tower.py):
        ``{"tower": {"base": {"sparse-cyclotomic": ...}, "levels": [{"radicand": r_i,
        "kummer": true}, ...], "kummer": [{"prime": p}, ...]}}``, the primes p = 1 mod N
        whose Legendre symbols (r_i | p) have rank L over F_2; numbers are base numbers
        {e: c} or [i, A, B] = A + B y_i.  A tower without levels is the sparse field."""
        self.field = None
        self.sparse = tower.context
        leaves = [leaf for v in values for leaf in _leaves(
            v.v if isinstance(v, TowerElement) else v)]
        base = self._sparse_spec(tower.context, leaves + [leaf for r in tower.radicands
                                                         for leaf in _leaves(r)])
        if not tower.radicands:
            self.spec = base
            return
        self.tower = tower
        rational = tower.radicands[:len(tower.radicands) - tower.nested]
        levels = [{"radicand": rational_text(r.to_fmpq()), "kummer": True} for r in rational]
        self.spec = {"tower": {"base": base, "levels": levels}}
        if rational:
            primes = legendre_rank_primes(tower.conductor, rational, MR_LIMIT)
            if primes is None:
                raise CertificateError(f"no primes below {MR_LIMIT} prove the square roots "
                                       f"of {tower.name} independent; cannot certify")
            self.spec["tower"]["kummer"] = [{"prime": str(p)} for p in primes]
        if tower.levels > len(rational):
            self._nested_levels(tower, levels, len(rational))

    def _nested_levels(self, tower, levels: list, first: int) -> None:
        """The certificates of a tower's nested levels over the sparse base (above the
        ``first`` rational ones): input does not reach them (a configuration's tower has
        rational levels only; the sparse nested reading that would add nested ones, and
        this writer, are tests/reference/sparse_nested_reading.py), so refused here."""
        raise CertificateError(f"{tower.name} has a nested level over the sparse base, which "
                               "no input reaches; cannot certify")

    def _sparse_text(self, x):
        """A real sparse number as {e: c} = sum c cos(2 pi e/N) (e and N - e merged); in a
        tower over the sparse base, a raw value's [i, A, B] = A + B y_i."""
        if isinstance(x, TowerElement):
            x = x.v
        if type(x) is tuple:
            return [x[0], self._sparse_text(x[1]), self._sparse_text(x[2])]
        if not isinstance(x, SparseCyclotomic):
            return rational_text(x.to_fmpq() if isinstance(x, FieldElement) else fmpq(x))
        if x.den is not None:
            raise CertificateError("a quotient of sparse cyclotomic numbers cannot be written")
        n = self.sparse.n
        out: dict = {}
        for e, c in x.num.items():
            k = min(e, n - e) if e else 0
            out[k] = out.get(k, fmpq(0)) + c
        out = {k: c for k, c in out.items() if c != 0}
        if not out:
            return "0"
        if list(out) == [0]:
            return rational_text(out[0])
        return {str(k): rational_text(c) for k, c in sorted(out.items())}

    def sparse_matrix(self, matrix) -> dict:
        """``{"matrix": ..., "scale": k}``: a sparse isometry matrix times a common denominator
        k (the entries are quotients num/den of one den, or rationals)."""
        entries, scale = self.sparse_homogeneous([e for row in matrix for e in row])
        return {"matrix": [entries[:2], entries[2:]], "scale": scale}

    def sparse_homogeneous(self, values) -> tuple[list, object]:
        """(texts of k v for v in values, text of k): k a common denominator of the values
        (quotients num/den of one den, or plain sums; in a tower, of the base numbers of
        their [i, A, B] forms), checked exactly."""
        one = SparseCyclotomic(self.sparse, {0: fmpq(1)})
        entries = [e.v if isinstance(e, TowerElement) else one * e for e in values]
        den = next((e.den for v in entries for e in _leaves(v) if e.den is not None), None)
        scale = SparseCyclotomic(self.sparse, den) if den is not None else one

        def times_scale(e):
            if type(e) is tuple:
                return (e[0], times_scale(e[1]), times_scale(e[2]))
            if e.den is None:
                return e * scale
            if e.den == den:                    # num/den times den: num
                return SparseCyclotomic(self.sparse, e.num)
            s = SparseCyclotomic(self.sparse, e.num) \
                if SparseCyclotomic(self.sparse, e.den) == scale else None
            if s is None or s != e * scale:     # e = s / scale, exactly
                raise CertificateError("numbers of a witness have no common denominator")
            return s
        scaled = [times_scale(e) for e in entries]
        return [self._sparse_text(v) for v in scaled], self._sparse_text(scale)

    def _square_roots(self, values):
        """The field Q(sqrt p) over the primes p of the radicands (pairwise coprime, none a
        square: the checker's "radicands" field); an element is {radicand: coefficient}."""
        primes: set = set()
        for v in values:
            if isinstance(v, MQ):
                for m in v.terms:
                    primes.update(int(p) for p, _ in fmpz(m).factor())
        self.field = None
        self.radicands = sorted(primes)
        self.spec = {"radicands": [str(p) for p in self.radicands]}

    def _tower(self, tower, values):
        """K_0 = Q(sqrt p) over the tower's base primes, then each level's radicand with a
        homomorphism to F_p proving it a non-square in the field below (checker/ext_tower.py)."""
        if isinstance(tower, SparseKummerTower):
            self._sparse_tower(tower, values)
            return
        if isinstance(tower, CyclotomicTower):
            self._cyclotomic_tower(tower)
            return
        def entry(r, p, base, roots):
            return {"radicand": _tower_text(r), "prime": p, "base": [str(s) for s in base],
                    "roots": [str(t) for t in roots]}
        self.field, self.tower = None, tower
        self.spec = {"tower": {"radicands": [str(p) for p in tower.primes]}}
        try:
            self.spec["tower"]["levels"] = _level_proofs(tower, nonsquare_witness, entry)
            return
        except CertificateError:
            # a proof per level needs a prime at which every lower radicand is a residue;
            # radicands of K_0 are proved new together by characters of full rank
            prefix = next((i for i, r in enumerate(tower.radicands) if not isinstance(r, MQ)),
                          len(tower.radicands))
            maps = base_kummer_witness(tower.primes, tower.radicands[:prefix]) if prefix \
                else None
            if maps is None:
                raise
        self.spec["tower"]["levels"] = \
            [{"radicand": _tower_text(r), "kummer": True} for r in tower.radicands[:prefix]] + \
            _level_proofs(tower, nonsquare_witness, entry, start=prefix + 1)
        self.spec["tower"]["kummer"] = [{"prime": p, "base": [str(s) for s in base]}
                                        for p, base in maps]

    def _cyclotomic_tower(self, tower):
        """K_0 = Q(theta), theta = 2cos(2pi/M), written as the real-cyclotomic field below
        (its elements converted to powers of theta), then each level's radicand with a prime
        p = 1 mod M and the roots of Psi_M modulo p (checker/ext_tower.py; docs/certificates.md,
        "Towers over Q(zeta_M)")."""
        self.field = tower.field
        self.atoms = None
        self._cyclotomic(tower.field)
        base = self.spec
        self.tower = tower
        if not tower.radicands:         # every radical denested: the real-cyclotomic field
            return
        if tower.classes is not None:   # square roots of rationals only: one joint proof
            primes = kummer_witness(tower)
            if primes is None:
                raise CertificateError(f"no primes below 2^40 prove the square roots of "
                                       f"{tower.name} independent; cannot certify")
            levels = [{"radicand": self._tower_text(r), "kummer": True}
                      for r in tower.radicands]
            self.spec = {"tower": {"base": base, "levels": levels, "kummer": [
                {"prime": p, "theta": [str(h) for h in thetas]} for p, thetas in primes]}}
            return
        levels = _level_proofs(tower, cyclotomic_nonsquare_witness,
                               lambda r, p, thetas, roots: {
                                   "radicand": self._tower_text(r), "prime": p,
                                   "theta": [str(h) for h in thetas],
                                   "roots": [str(t) for t in roots]})
        self.spec = {"tower": {"base": base, "levels": levels}}

    def _tower_text(self, v):
        """A raw value of a tower over Q(zeta_M): a rational, {"theta": [c_0, ...]} in the
        base (coefficients of powers of theta = 2cos(2pi/M)), or [i, a, b] = a + b y_i."""
        if type(v) is tuple:
            return [v[0], self._tower_text(v[1]), self._tower_text(v[2])]
        value = self.convert(v)
        if isinstance(value, fmpq):
            return rational_text(value)
        if value.degree() <= 0:
            return rational_text(value.coeffs()[0] if value.degree() == 0 else 0)
        coeffs = [rational_text(c) for c in value.coeffs()]
        return {"theta": coeffs} if self.tower.radicands else coeffs

    # -- the real subfield of Q(zeta_M)
    def _cyclotomic(self, field):
        m = field.conductor
        phi = fmpz_poly.cyclotomic(m).coeffs()
        h = (len(phi) - 1) // 2
        theta = fmpq_poly([0, 1])
        v_prev, v = fmpq_poly([2]), theta
        psi = fmpq_poly([phi[h]])
        for k in range(1, h + 1):
            psi += int(phi[h + k]) * v
            v_prev, v = v, theta * v - v_prev
        if psi.degree() <= 1:
            raise CertificateError(f"Q(zeta_{m}) has a rational real subfield, yet an "
                                   "irrational real number was found")
        self.minpoly = psi
        self.basis = [fmpq_poly([1])]           # basis[k] = V_k(theta) / 2 mod Psi_M
        v_prev, v = fmpq_poly([2]), theta
        for _ in range(1, field.degree):
            self.basis.append((v / 2) % psi)
            v_prev, v = v, (theta * v - v_prev) % psi

        def enclose(prec):
            with ctx.workprec(prec + 16):
                return 2 * arb.cos_pi_fmpq(fmpq(2, m))
        self._finish(enclose, {"method": "real-cyclotomic", "conductor": m})

    def _general(self, field):
        self.minpoly = field.minpoly
        self.basis = None
        d = field.minpoly.degree()
        coeffs = [Fraction(int(c.p), int(c.q)) for c in field.minpoly.coeffs()]
        den = math.lcm(*(c.denominator for c in coeffs))
        ints = [int(c * den) for c in coeffs]
        for prime in _primes(5000):
            if ints[-1] % prime == 0:
                continue
            factors = nmod_poly([c % prime for c in ints], prime).factor()[1]
            if len(factors) == 1 and factors[0][1] == 1 and factors[0][0].degree() == d:
                self._finish(field.enclosure, {"method": "prime", "prime": prime})
                return
        proof = square_root_proof(field, self.atoms)
        if proof is not None:
            self._finish(field.enclosure, proof)
            return
        raise CertificateError(f"neither a prime below 5000 nor square roots of integers "
                               f"prove the minimal polynomial of {field.name} irreducible; "
                               "this field cannot be certified")

    def _finish(self, enclose, proof):
        coeffs = [Fraction(int(c.p), int(c.q)) for c in self.minpoly.coeffs()]
        lo, hi = _isolating_interval(coeffs, enclose)
        self._enclose = enclose
        self.spec = {"minpoly": [rational_text(_to_fmpq(c)) for c in coeffs],
                     "interval": [rational_text(_to_fmpq(lo)), rational_text(_to_fmpq(hi))],
                     "irreducible": proof}

    def convert(self, x) -> fmpq_poly | fmpq:
        """x as a polynomial in theta (or as a rational)."""
        if not isinstance(x, FieldElement):
            return fmpq(x) if not isinstance(x, fmpq) else x
        if x.is_rational():
            return x.to_fmpq()
        if isinstance(x, MQ):
            x = self.field(x)                   # the Gauss sums of its square roots
        if self.basis is None:
            return x.poly
        result = fmpq_poly([0])
        for c, b in zip(x.poly.coeffs(), self.basis):
            if c != 0:
                result += c * b
        # the conversion is an identity of real numbers: check it numerically (a cheap guard)
        with ctx.workprec(100):
            if not arb_poly(result)(self._enclose(84)).overlaps(x.enclosure(84)):
                raise CertificateError("real-subfield conversion failed (bug)")
        return result

    def text(self, x):
        if self.sparse is not None:
            return self._sparse_text(x)
        if isinstance(self.tower, CyclotomicTower):
            return self._tower_text(x.v if isinstance(x, TowerElement) else
                                    x.to_fmpq() if isinstance(x, FieldElement) else fmpq(x))
        if self.tower is not None:
            return _tower_text(x.v if isinstance(x, TowerElement) else
                               x if isinstance(x, MQ) else MQ.rational(x))
        if self.radicands is not None:
            if isinstance(x, MQ):
                if x.is_rational():
                    return rational_text(x.to_fmpq())
                return {str(m): rational_text(c) for m, c in sorted(x.terms.items())}
            return rational_text(x.to_fmpq() if isinstance(x, FieldElement) else x)
        value = self.convert(x)
        if isinstance(value, fmpq):
            return rational_text(value)
        if value.degree() <= 0:
            return rational_text(value.coeffs()[0] if value.degree() == 0 else 0)
        return [rational_text(c) for c in value.coeffs()]


def _level_proofs(tower, witness, entry, start: int = 1) -> list:
    """Each level's radicand from level ``start`` on with its non-square proof
    (``witness(tower, i)``: a prime and the data the checker re-runs), written by
    ``entry(radicand, *proof)``."""
    levels = []
    for i, r in enumerate(tower.radicands[start - 1:], start=start):
        proof = witness(tower, i)
        if proof is None:
            raise CertificateError(f"no prime below 200000 proves the radicand of level {i} "
                                   f"of {tower.name} a non-square; cannot certify")
        levels.append(entry(r, *proof))
    return levels


def _leaves(v) -> list:
    """The base numbers of a raw tower value (a base number: itself)."""
    if type(v) is tuple:
        return _leaves(v[1]) + _leaves(v[2])
    return [v]


def _tower_text(v):
    """A raw tower value (exact/tower.py) in the certificate: a rational, {m: c} in the base,
    or [i, a, b] = a + b y_i."""
    if isinstance(v, MQ):
        if v.is_rational():
            return rational_text(v.to_fmpq())
        return {str(m): rational_text(c) for m, c in sorted(v.terms.items())}
    return [v[0], _tower_text(v[1]), _tower_text(v[2])]


def _primes(limit: int):
    sieve = bytearray([1]) * limit
    for p in range(2, limit):
        if sieve[p]:
            yield p
            sieve[p * p::p] = bytearray(len(range(p * p, limit, p)))

"""Square roots in the multiquadratic closure beyond RATIONAL_BITS
(exactsym.exact.mq_closure): the Kummer search carries its free rational m unfactored,
and a root is written with m's square-free part found by a bounded split."""

from flint import fmpz
from hypothesis import given, settings, strategies as st

from exactsym.exact.mq_closure import RATIONAL_BITS, bounded_squarefree_split, decided_sqrt
from exactsym.exact.multiquadratic import sqrt_rational

S2 = sqrt_rational(2)
def _prime_above(k: int) -> int:
    n = fmpz(k) | 1
    while not n.is_prime():
        n += 2
    return int(n)


BIG1 = _prime_above(2 ** 200 + 12345)
BIG2 = _prime_above(3 ** 130 + 777)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.sampled_from([2, 3, 5, 7, 13, 65537, 2 ** 31 - 1, 1000003,
                                           2 ** 61 - 1]), st.integers(1, 5)),
                min_size=1, max_size=5),
       st.sampled_from([1, BIG1, BIG1 ** 2, BIG1 ** 3]))
def test_bounded_split_is_exact(parts, big):
    """Never a wrong split; and always one when every other prime is below 2^17 (what
    ECM may miss is a prime of more bits, then the answer is None)."""
    n, odd = big, {}
    for p, e in parts:
        n *= p ** e
        odd[p] = odd.get(p, 0) + e
    expect_m = 1
    for p, e in odd.items():
        if e % 2:
            expect_m *= p
    if big in (BIG1, BIG1 ** 3):
        expect_m *= BIG1
    split = bounded_squarefree_split(n)
    if split is None:
        assert any(p > 2 ** 17 for p in odd)
        return
    s, m = split
    assert s * s * m == n and m == expect_m


def test_a_product_of_two_large_primes_is_left_undecided():
    assert bounded_squarefree_split(BIG1 * BIG2 * 12) is None


def test_a_composite_that_ecm_leaves_is_factored_when_small_enough(monkeypatch):
    """Two primes of 64 and 72 bits (ECM looks for 48 and misses both: without the full
    factoring the split is None): their product, times smooth parts and a square, is
    split in full (up to FULL_FACTOR_BITS bits)."""
    from exactsym.exact import mq_closure
    p, q = _prime_above(2 ** 64 + 99), _prime_above(2 ** 72 + 5)
    n = p * q * 12 * 49
    s, m = bounded_squarefree_split.__wrapped__(n)
    assert s * s * m == n and m == 3 * p * q
    monkeypatch.setattr(mq_closure, "FULL_FACTOR_BITS", 0)
    assert bounded_squarefree_split.__wrapped__(n) is None
    # beyond the bound: test_a_product_of_two_large_primes_is_left_undecided (406 bits)
    assert (BIG1 * BIG2).bit_length() > 216


def test_a_root_with_a_large_prime_radicand_is_found():
    # x = m w^2, m = 6 BIG1 (more than RATIONAL_BITS bits), w = 3 + sqrt 2: its root
    # sqrt(6 BIG1) (3 + sqrt 2) lies in Q(sqrt 2, sqrt(3 BIG1)); before, "undecided"
    m = 6 * BIG1
    assert m.bit_length() > RATIONAL_BITS
    w = 3 + S2
    x = w * w * m
    root, decided = decided_sqrt(x)
    assert decided and root is not None and root * root == x and root.sign() > 0
    assert (3 * BIG1) in root.radicands() or (6 * BIG1) in root.radicands()


def test_a_root_whose_radicand_cannot_be_split_is_undecided():
    x = (1 + S2) ** 2 * (BIG1 * BIG2)
    root, decided = decided_sqrt(x)
    assert root is None and not decided


def test_no_root_is_decided_without_factoring():
    # the norm of 1 + BIG1 sqrt 2 is 1 - 2 BIG1^2 < 0: no root anywhere, decided
    x = 1 + S2 * BIG1
    x = x * x + S2                     # positive; its norm is not a square
    root, decided = decided_sqrt(x)
    assert root is None and decided


def test_hints_cut_what_ecm_would_not_find():
    # two large primes: no bounded ECM splits their product, a hint that holds one does
    n = BIG1 * BIG2 * BIG2 * 10
    assert bounded_squarefree_split(n) is None
    s, m = bounded_squarefree_split(n, (BIG2 * 7,))
    assert (s, m) == (BIG2, 10 * BIG1)
    # a wrong hint (not a divisor) changes nothing
    assert bounded_squarefree_split(n, (BIG1 + 2,)) is None


def test_without_the_split_a_large_root_is_undecided():
    # the paper layer's MakeAsym move (adjoin_sqrt) asks without the bounded split
    m = 6 * BIG1
    x = (3 + S2) ** 2 * m
    assert decided_sqrt(x, bounded=False) == (None, False)
    root, decided = decided_sqrt(x)
    assert decided and root * root == x


_PRIMES = (2, 3, 5, 7, 11)


def _mq(draw_terms):
    from exactsym.exact.multiquadratic import MQ
    from flint import fmpq
    out = MQ()
    for (mask, num, den) in draw_terms:
        m = 1
        for k, p in enumerate(_PRIMES):
            if mask >> k & 1:
                m *= p
        out = out + MQ({m: fmpq(num, den)})
    return out


_terms = st.lists(st.tuples(st.integers(0, 31), st.integers(-9, 9).filter(bool),
                            st.integers(1, 6)), min_size=1, max_size=6)


@settings(max_examples=120, deadline=None)
@given(_terms, st.sampled_from([1, 2, 6, 13, 15, 77, 2 * 3 * 5 * 7 * 11 * 13]))
def test_the_modular_filter_never_refutes_a_root(terms, m):
    """mq_closure._refuted_modulo on m w^2: a root sqrt(m) w exists, so the filter must
    not refute it (free), nor w^2 when m = 1 (a root in K itself)."""
    from exactsym.exact.mq_closure import _refuted_modulo
    w = _mq(terms)
    if w.is_zero():
        return
    y = w * w * m
    assert not _refuted_modulo(y, _PRIMES, True)
    if m == 1:
        assert not _refuted_modulo(y, _PRIMES, False)


@settings(max_examples=80, deadline=None)
@given(_terms, _terms)
def test_the_modular_filter_changes_no_answer(t1, t2):
    """decided_sqrt with and without the filter: the same root, or the same None."""
    import exactsym.exact.mq_closure as closure
    y = _mq(t1) * _mq(t1) + _mq(t2)
    if y.sign() <= 0:
        return
    with_filter = decided_sqrt(y)
    saved = closure._refuted_modulo
    closure._refuted_modulo = lambda *a: False
    try:
        assert decided_sqrt(y) == with_filter
    finally:
        closure._refuted_modulo = saved


def test_the_modular_filter_refutes_a_non_square():
    """1 + sqrt 2 + sqrt 3 is no m w^2 (its conjugates have both signs); 3 + 2 sqrt 2 =
    (1 + sqrt 2)^2 is a square, 3 (3 + 2 sqrt 2) is 3 w^2, a free root."""
    from exactsym.exact.mq_closure import _refuted_modulo
    from exactsym.exact.multiquadratic import MQ
    from flint import fmpq
    y = MQ({1: fmpq(1), 2: fmpq(1), 3: fmpq(1)})
    assert _refuted_modulo(y, (2, 3), True)
    sq = MQ({1: fmpq(3), 2: fmpq(2)})
    assert not _refuted_modulo(sq, (2,), False)
    assert not _refuted_modulo(sq * 3, (2,), True)

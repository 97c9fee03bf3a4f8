"""Real algebraic numbers for motion: roots of polynomials with multiquadratic coefficients.

The gathering simulator's critical instants are real roots of small polynomials whose
coefficients are multiquadratic numbers; the positions at them, and the targets a Look
computes there, are numbers of towers over those fields.  This package holds them, from
the bottom up:

* :mod:`.polynomials` -- polynomial arithmetic over the coefficients' field;
* :mod:`.sturm` -- Sturm chains, square-free parts, Arb filters that exclude roots;
* :mod:`.factor` -- factoring over a multiquadratic field (Trager);
* :mod:`.tower_numbers` -- nested radicals: a root in a tower of quadratic extensions;
* :mod:`.algebraic_numbers` -- numbers of ``K(alpha)``, alpha a root of a factor that
  square roots do not express; :mod:`.algebraic_tower` -- square roots over it;
* :mod:`.run_tower` -- one growing tower per run (nested-radical positions);
* :mod:`.quartic` -- roots of quartics of group D4, C4, V4 (Ferrari);
* :mod:`.roots` -- exact real-root isolation in (0, 1) and the exact value of a root;
* :mod:`.interface` -- what every such number offers, and the questions about its kind
  that code outside ``exact/`` asks instead of ``isinstance``.
"""

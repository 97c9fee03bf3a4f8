(* Refutation of lem-vl-move, checked by Coq: `coqc` on this file alone.
   The paper: Lemma lem-vl-move: 'When v_l is moving no other robot will be selected as leader.'
   The ledger (proofs/statements.toml): While v_l moves, no other robot is selected as leader.
   Refuted under the reading: 'selected as leader' by any step of the procedure, GatheringPattern's ElectLeader included (the paper's own use, L1562: 'when the leader is moving, no other robots will move'); Preprocess with its counters advancing (calG' = calG when no G_ij is type 4); MakeAsym's 'Move v_l, epsilon distance away' a turn of eps = 1/100 about C (as its FindAsymmetry branch says, 'on the same circle'), in either sense, the fresh Look half way (lam = 1/2); ElectLeader's branch decided by G_1's symmetry itself (Check_Symmetry_Odd as printed never ends on G_1; read with i++ after every vertex it reports the same). No reading of a one-robot G_1 and no ordering: the leader is a vertex of G_1 whichever Elect_Leader_Asym picks.
   Written by exactsym (exactsym/certificates/coq_gathering.py); the libraries
   below are proofs/coq/Exactsym.v and proofs/coq/Gathering.v, inlined: they
   hold every definition used.
   source: cases/gathering/polar-makeasym-mover-triangle-g1.toml *)

(* Exactsym.v -- the definitions of Gan Chaudhuri and Mukhopadhyaya, "Leader Election and
   Gathering for Asynchronous Transparent Fat Robots without Chirality", that exactsym's
   refutations use, as decision procedures over exact rationals.  Every exported refutation
   (exactsym certify --refutes LABEL FILE --coq OUT.v) inlines this file and proves, by
   computation, that its configuration meets the statement's hypotheses and falsifies its
   conclusion.  This file is the trusted base of those refutations: read it against the
   paper (its \label names are cited at each definition); docs/certificates.md, "Coq".

   The configurations are RATIONAL POLAR ones about C, the centre of the smallest
   enclosing circle (SEC) of P: a point is (r2, turn), its squared distance from C and its
   angle as a fraction of a full turn.  (1, 0) and (1, 1) are one point, so points are
   compared by [peq], never by Coq's syntactic equality.

   What a reader trusts besides the definitions (each argued where it is used):
   (T1) [sec_centred P] implies that C (the origin) is the centre of the SEC of P;
   (T2) every isometry of the plane mapping P onto itself is one of [candidates P]
        (the SEC is unique, so such an isometry fixes C: it is a rotation about C or a
        reflection in a line through C, and it maps the anchor to a point at its
        distance from C, which leaves the candidates);
   (T3) for the polygons of G_P (points on one circle about C, at least three of them)
        the same holds with the polygon in place of P (three points on a circle determine
        it, so a symmetry of the polygon fixes C).
   (T4) [separated P] implies that every two robots of P (unit discs, "fat robots")
        are more than 2 apart: four sufficient tests, argued before [robots_apart]
        (the sine bound the chord test uses is proved: [sin_lower_bound]).
   Negative facts ("no line of symmetry", "asymmetric") rest on (T1)-(T3); positive
   facts (a symmetry exists) and "not orderable" do not: the latter is a Coq theorem
   ([not_orderable_by_candidates]) from the definition of def-orderable-set below.  The
   definition lists P's points as points ([mem]), so it does not depend on how P's terms
   are written; the theorem needs P written canonically ([canonical P], checked), and
   then a symmetry whose canonical image of p is another term maps p to another point
   ([canon_peq]).
   "Orderable" and "electable" are Coq theorems too, but they rest on (T1), not on
   (T2): [orderable] and [electable] ask for equivariance under the isometries ABOUT C
   only, which is the paper's notion only when C is the centre of P's SEC (every isometry
   mapping P onto itself fixes that centre).  For an off-centre set a symmetry of P need
   not fix C, and the definition can be met by a set the paper proves not orderable
   (two points, or an isosceles triangle with C at a base vertex).  So
   [orderable_of_only_identity] and [electable_of_only_identity] take [sec_centred P]
   (formally unused by the proof; it is what makes the conclusion the paper's), and every
   exported theorem states [sec_centred P] of its whole configuration.  Given (T1), (T2)
   is proved for the isometries about C ([candidates_complete]: every isometry about C
   mapping P into itself acts as one of [candidates P]), and a set whose candidates
   mapping it onto itself all fix it pointwise ([only_identity P], computed) is
   orderable ([orderable_of_only_identity]); a leader ([electable]: a robot every
   observer designates) likewise: "no leader" when a symmetry moves every robot
   ([not_electable_by_candidates]), a leader when the identity is the only symmetry
   ([electable_of_only_identity]).
   The other coordinate changes of def-orderable-set (another origin, another unit, an
   axis at an irrational angle: a similarity s) are not in [orderable].  For a set whose
   only symmetry is the identity they add nothing, by this argument (not formalised):
   define order'(A) as s applied to [order_by_images P P] when A is s(P) for a
   similarity s, and [] otherwise.  It is well defined: if s(P) = s'(P), then s'^-1 s
   maps P onto itself, keeps P's SEC (unique), so it has ratio 1 and fixes C (T1); it
   takes the anchor to a point of P at the anchor's distance from C, so it is one of
   [candidates P] (T2's argument, for any angle), hence the identity on P
   ([only_identity P]) and s, s' agree on P.  It commutes with every similarity by
   construction and lists every point of P.  This is [order_by_images] with similarities
   for the isometries about C; the Coq proof covers the rational isometries about C.
   The "not orderable" theorems need no such argument: fewer coordinate changes make
   "orderable" easier to meet, so "not orderable" is the stronger claim. *)

From Coq Require Import QArith ZArith List Bool Lia.
From Coq Require Reals Qreals Lra.       (* only for [sin_lower_bound], at the end *)
Import ListNotations.
Open Scope Q_scope.

(* ------------------------------------------------------------------ numbers and points *)

(* Two turns are one angle iff they differ by an integer. *)
Definition integral (q : Q) : bool := Z.eqb (Z.modulo (Qnum q) (Zpos (Qden q))) 0.
Definition teq (a b : Q) : bool := integral (a - b).
(* The representative of a turn in [0, 1). *)
Definition frac (q : Q) : Q := Qmake (Z.modulo (Qnum q) (Zpos (Qden q))) (Qden q).

(* x < y on Q, decided. *)
Definition Qlt_bool (x y : Q) : bool := negb (Qle_bool y x).

Record pt := Pt { r2 : Q; turn : Q }.

(* One point: the same distance from C and, off C, the same angle. *)
Definition peq (p q : pt) : bool :=
  Qeq_bool (r2 p) (r2 q) && (Qeq_bool (r2 p) 0 || teq (turn p) (turn q)).

Definition mem (p : pt) (P : list pt) : bool := existsb (peq p) P.

(* A set of points: no point listed twice. *)
Fixpoint distinct (P : list pt) : bool :=
  match P with [] => true | p :: rest => negb (mem p rest) && distinct rest end.

Definition same_set (P Q : list pt) : bool :=
  forallb (fun p => mem p Q) P && forallb (fun q => mem q P) Q.

(* ------------------------------------------------------------------ isometries about C *)

(* [Rot a]: the rotation about C by a turns.  [Mirror s]: the reflection in the line
   through C at angle s/2 turns (turn t goes to s - t); Mirror s and Mirror (s + 1) are
   one reflection.  stmirrorimage: the straight mirror image of p across that line is
   [act (Mirror s) p].  skmirrorimage, read with m = C (the project's reading, ledger
   entry skmirrorimage): the skewed mirror image across any line through C is the
   half-turn [act (Rot (1#2)) p]. *)
Inductive iso := Rot (a : Q) | Mirror (s : Q).

Definition act (g : iso) (p : pt) : pt :=
  match g with
  | Rot a => Pt (r2 p) (turn p + a)
  | Mirror s => Pt (r2 p) (s - turn p)
  end.

(* g maps P onto itself.  g is injective and P finite and distinct, so "into" is "onto". *)
Definition is_symmetry (g : iso) (P : list pt) : bool := forallb (fun p => mem (act g p) P) P.

Definition moves (g : iso) (P : list pt) : bool := existsb (fun p => negb (peq (act g p) p)) P.

Definition half_turn : iso := Rot (1 # 2).

(* ------------------------------------------------------------------ the SEC and candidates *)

Definition rmax (P : list pt) : Q :=
  fold_left (fun m p => if Qle_bool m (r2 p) then r2 p else m) P 0.
Definition rim (P : list pt) : list pt := filter (fun p => Qeq_bool (r2 p) (rmax P)) P.

(* (T1): every point is within sqrt(rmax) of C by the definition of rmax, and the points
   at that distance leave no angular gap above half a turn: each has another one at most
   half a turn counter-clockwise.  Then no open half-plane bounded by a line through C
   holds them all: for any other centre C' one of them, s, has (s - C).(C' - C) <= 0, so
   |s - C'|^2 = R^2 + |C' - C|^2 - 2 (s - C).(C' - C) > R^2 and no circle about C' of
   radius at most R holds P: the SEC is the circle of radius R about C. *)
Definition next_within_half (p q : pt) : bool :=
  let g := frac (turn q - turn p) in Qlt_bool 0 g && Qle_bool g (1 # 2).
Definition sec_centred (P : list pt) : bool :=
  forallb (fun p => Qle_bool 0 (r2 p)) P &&
  forallb (fun p => existsb (next_within_half p) (rim P)) (rim P).

(* The first point off C: every symmetry maps it to a point at its distance from C. *)
Fixpoint anchor (P : list pt) : option pt :=
  match P with
  | [] => None
  | p :: rest => if Qlt_bool 0 (r2 p) then Some p else anchor rest
  end.

(* (T2): the rotation about C and the reflection in a line through C taking the anchor a
   to each point q at a's distance. *)
Definition candidates (P : list pt) : list iso :=
  match anchor P with
  | None => []
  | Some a => flat_map (fun q => if Qeq_bool (r2 q) (r2 a)
                                 then [Rot (turn q - turn a); Mirror (turn q + turn a)]
                                 else []) P
  end.

Definition symmetries (P : list pt) : list iso := filter (fun g => is_symmetry g P) (candidates P).

(* The reflections among the symmetries, by their parameter s (distinct for distinct q:
   these are the lines of straight symmetry, each once). *)
Definition mirror_of (g : iso) : list Q := match g with Mirror s => [s] | Rot _ => [] end.
Definition mirrors (P : list pt) : list Q := flat_map mirror_of (symmetries P).

(* ------------------------------------------------------------------ configurations *)

(* def-straight-symmetric-conf: a line L not containing all of P whose reflection maps P
   onto itself (points on L are their own images).  Its reflection fixes every point iff L
   contains all of P, so L must move a point. *)
Definition straight_symmetric (P : list pt) : bool :=
  existsb (fun s => moves (Mirror s) P) (mirrors P).

(* def-skewed-symmetric-conf, with the skewed mirror image read as the half-turn about C
   (skmirrorimage, m = C): a line through C, not containing all of P (for P non-empty,
   one that misses a point off C always exists), whose skewed images map P onto itself. *)
Definition skew_symmetric (P : list pt) : bool := is_symmetry half_turn P.

(* def-symmetric-conf: a singleton, or straight or skew symmetric.  def-asymmetric-conf:
   not symmetric (P in O_A).  The empty set has no line "not containing all the points of
   P" (every line contains all of none), so it is neither straight nor skew symmetric:
   the half-turn maps it onto itself vacuously, hence the test of non-emptiness. *)
Definition symmetric_conf (P : list pt) : bool :=
  Nat.eqb (length P) 1 || straight_symmetric P ||
  (negb (Nat.eqb (length P) 0) && skew_symmetric P).
Definition in_O_A (P : list pt) : bool := negb (symmetric_conf P).

(* ------------------------------------------------------------------ fat robots *)

(* Robots are unit discs ("fat robots", radius one): two robots overlap iff their centres
   are less than 2 apart.  "We are given a set, R, of separated, stationary transparent
   fat robots"; GatheringPattern's input: "R, the set of separated robots".  (T4): four
   sufficient tests that two robots are more than 2 apart, none needs a cosine.  Write a,
   b for the distances from C (a^2 = r2 p, b^2 = r2 q) and g in [0, 1/2] for the angular
   gap in turns.
   - [quarter_apart]: g >= 1/4, so cos(2 pi g) <= 0 and |p - q|^2 = a^2 + b^2 -
     2ab cos(2 pi g) >= a^2 + b^2 > 4.
   - [sixth_apart]: g >= 1/6, so cos(2 pi g) <= 1/2 and, for a <= b, |p - q|^2 >=
     a^2 + b^2 - ab = a^2 + b (b - a) >= a^2 = min(a^2, b^2) > 4.
   - [radially_apart]: |p - q| >= |b - a| (triangle inequality through C), and for
     a^2 <= b^2, b - a > 2 iff b > a + 2 iff b^2 > a^2 + 4a + 4 iff
     b^2 - a^2 - 4 > 4a iff (b^2 - a^2 - 4 > 0 and (b^2 - a^2 - 4)^2 > 16 a^2).
   - [chord_apart]: one circle (a = b) and 0 < g <= 1/4: p, q and C form an isosceles
     triangle with apex angle 2 pi g, so |p - q| = 2a sin(pi g), and
     sin(pi g) >= 3g - 9/2 g^3 > 0 ([sin_lower_bound], proved at the end of this file), so
     |p - q|^2 >= 4 a^2 (3g - 9/2 g^3)^2 > 4 when a^2 (3g - 9/2 g^3)^2 > 1.  (Robots on
     one circle a small turn apart: the other three tests never pass them.) *)
Definition angular_gap (p q : pt) : Q :=
  let g := frac (turn p - turn q) in if Qle_bool g (1 # 2) then g else 1 - g.
Definition quarter_apart (p q : pt) : bool :=
  Qle_bool (1 # 4) (angular_gap p q) && Qlt_bool 4 (r2 p + r2 q).
Definition sixth_apart (p q : pt) : bool :=
  Qle_bool (1 # 6) (angular_gap p q) && Qlt_bool 4 (r2 p) && Qlt_bool 4 (r2 q).
Definition radially_apart (p q : pt) : bool :=
  let a2 := if Qle_bool (r2 p) (r2 q) then r2 p else r2 q in
  let b2 := if Qle_bool (r2 p) (r2 q) then r2 q else r2 p in
  let d := b2 - a2 - 4 in Qlt_bool 0 d && Qlt_bool (16 * a2) (d * d).
Definition sine_bound (g : Q) : Q := 3 * g - (9 # 2) * (g * g * g).
Definition chord_apart (p q : pt) : bool :=
  let g := angular_gap p q in
  Qeq_bool (r2 p) (r2 q) && Qlt_bool 0 g && Qle_bool g (1 # 4) &&
  Qlt_bool 1 (r2 p * (sine_bound g * sine_bound g)).
Definition robots_apart (p q : pt) : bool :=
  quarter_apart p q || sixth_apart p q || radially_apart p q || chord_apart p q.

(* (T4) The robots are separated: every two of them are more than 2 apart. *)
Fixpoint separated (P : list pt) : bool :=
  match P with
  | [] => true
  | p :: rest => forallb (robots_apart p) rest && separated rest
  end.

(* Coordinates are written canonically: the squared distance in lowest terms and, off C,
   the turn in [0, 1) in lowest terms (at C the turn 0).  Two canonical points are one
   point iff they are the same term (Qred gives the one lowest-terms form of a rational,
   frac the one representative in [0, 1) of a turn), so a point moved by g is one whose
   canonical image differs from it as a term.  [canonical P]: P is written so. *)
Definition canon (p : pt) : pt :=
  if Qeq_bool (r2 p) 0 then Pt 0 0 else Pt (Qred (r2 p)) (Qred (frac (turn p))).
Definition q_eqb (x y : Q) : bool := Z.eqb (Qnum x) (Qnum y) && Pos.eqb (Qden x) (Qden y).
Definition pt_eqb (p q : pt) : bool := q_eqb (r2 p) (r2 q) && q_eqb (turn p) (turn q).
Definition canonical (P : list pt) : bool := forallb (fun p => pt_eqb (canon p) p) P.

(* The coordinates of the points after the change of coordinates g, written canonically. *)
Definition image (g : iso) (p : pt) : pt := canon (act g p).

(* def-orderable-set: "a deterministic algorithm which produces a unique ordering of the
   points of P, such that the ordering is same irrespective of the choice of origin and
   coordinate system".  An algorithm [order] reads a set (lists of one set give one
   answer), lists every point of P (as a point: [mem], so how P's terms are written does
   not matter), and commutes with every change of coordinates among
   the isometries about C (requiring fewer coordinate changes makes "orderable" easier to
   meet, so "not orderable" below is the stronger claim).  Not vacuous: when no isometry
   about C other than the identity on P maps P onto itself, [order] may send the image of
   P under any g to the images, in a fixed order, of P's points (well defined because g
   is then determined on P), and any other set to the empty list: proved at the end of
   this file ([orderable_of_only_identity], with [order_by_images]). *)
Definition orderable (P : list pt) : Prop :=
  exists order : list pt -> list pt,
    (forall A B, same_set A B = true -> order A = order B) /\
    (forall g, order (map (image g) P) = map (image g) (order P)) /\
    (forall p, In p P -> mem p (order P) = true).

(* ------------------------------------------------------------------ polygons of G_P *)

Fixpoint radii (P : list pt) : list Q :=
  match P with
  | [] => []
  | p :: rest => let rs := radii rest in
                 if Qlt_bool 0 (r2 p) && negb (existsb (Qeq_bool (r2 p)) rs)
                 then r2 p :: rs else rs
  end.

(* The polygon at squared distance r from C (the text before def-sym-pair: "any polygon
   G_i can be extracted by selecting the equidistant points from the center"), and
   calG_P, the polygons of P. *)
Definition level (P : list pt) (r : Q) : list pt := filter (fun p => Qeq_bool (r2 p) r) P.
Definition polygons (P : list pt) : list (list pt) := map (level P) (radii P).

(* A convex polygon (lemma-sym-ord's proof: "convex polygons ... inscribed in a circle"
   about C) of at least three vertices, for which (T3) holds. *)
Definition polygon (G : list pt) : bool :=
  Nat.leb 3 (length G) && distinct G &&
  match G with [] => false | v :: _ =>
    Qlt_bool 0 (r2 v) && forallb (fun p => Qeq_bool (r2 p) (r2 v)) G end.

(* def-symmetric-poly, def-asymmetric-poly: the vertex set is (not) in symmetric
   configuration. *)
Definition symmetric_polygon (G : list pt) : bool := symmetric_conf G.
Definition asymmetric_polygon (G : list pt) : bool := negb (symmetric_conf G).

(* A line through C at angle s/2 turns is a line of symmetry of the polygon G: of
   straight symmetry (its reflection maps G onto G) or of skew symmetry (the half-turn
   maps G onto G; then every line through C is one).  This is the widest reading of
   "line of symmetry" (straight or skew, either for either polygon: the "mixed" reading of
   "common line"), so "no common line" here holds under every reading. *)
Definition line_of_symmetry (G : list pt) (s : Q) : bool :=
  is_symmetry (Mirror s) G || is_symmetry half_turn G.

(* def-sym-pair: <G_i, G_j> is symmetric iff they have a common line of symmetry.  If
   both have the half-turn every line through C is common; else a common line is a
   mirror of one without it, so the mirrors of both are the candidates. *)
Definition symmetric_pair (Gi Gj : list pt) : bool :=
  (is_symmetry half_turn Gi && is_symmetry half_turn Gj) ||
  existsb (fun s => line_of_symmetry Gi s && line_of_symmetry Gj s) (mirrors Gi ++ mirrors Gj).
Definition asymmetric_pair (Gi Gj : list pt) : bool := negb (symmetric_pair Gi Gj).

(* def-sym-calG: calG is symmetric (in O_S) iff all its polygons have a common line of
   symmetry; the candidates as for a pair. *)
Definition calG_symmetric (Gs : list (list pt)) : bool :=
  forallb (is_symmetry half_turn) Gs ||
  existsb (fun s => forallb (fun G => line_of_symmetry G s) Gs) (flat_map mirrors Gs).
Definition calG_in_O_A (Gs : list (list pt)) : bool := negb (calG_symmetric Gs).

(* The same-kind reading of "common line" (def-sym-pair, def-sym-calG): a line through C
   is common to the polygons Gs when it is a line of straight symmetry of every one (a
   mirror of each), or a line of skew symmetry of every one (the half-turn maps each onto
   itself; then every line through C is one).  A common straight line is a mirror of the
   first polygon, so the mirrors are the candidates.  For polygons of at least three
   vertices on a circle no line holds every vertex, so the readings that differ on such
   lines (or on single robots) agree with this one. *)
Definition common_line_same_kind (Gs : list (list pt)) : bool :=
  forallb (is_symmetry half_turn) Gs ||
  existsb (fun s => forallb (fun G => is_symmetry (Mirror s) G) Gs) (flat_map mirrors Gs).
Definition symmetric_pair_same_kind (Gi Gj : list pt) : bool :=
  common_line_same_kind [Gi; Gj].

(* Before obs-merg-asym-pair: "the vertices of G_i are projected radially on the
   circumference of the enclosing circle of G_j (i < j).  Construct a polygon G_ij with
   the full set of vertices on the circle."  A projected vertex on a vertex of G_j is one
   vertex of G_ij. *)
Definition merged (Gi Gj : list pt) : list pt :=
  match Gj with
  | [] => Gi
  | v :: _ => filter (fun p => negb (mem p Gj)) (map (fun p => Pt (r2 v) (turn p)) Gi) ++ Gj
  end.

(* ------------------------------------------------------------------ regular polygons, types *)

(* n distinct points on a circle about C form a regular n-gon iff the rotation by 1/n of
   a turn maps them onto themselves (then they are one orbit of it). *)
Definition regular (G : list pt) : bool :=
  polygon G && is_symmetry (Rot (1 # Pos.of_nat (length G))) G.

(* The line of Mirror s passes through the vertex v iff the reflection fixes v. *)
Definition fixed_vertices (G : list pt) (s : Q) : nat :=
  length (filter (fun v => peq (act (Mirror s) v) v) G).
Definition through_vertex (G : list pt) (s : Q) : bool := Nat.ltb 0 (fixed_vertices G s).

Definition prime (n : nat) : bool :=
  Nat.leb 2 n && forallb (fun d => negb (Nat.eqb (Nat.modulo n d) 0)) (seq 2 (n - 2)).

(* The types before obs-exh-poly, for a convex polygon G with the lines of straight
   symmetry [mirrors G] (n = number of vertices):
   type 0: "a regular convex symmetric polygon";
   type 1: non-regular, n even, exactly two lines of straight symmetry L1, L2, neither
           through a vertex, L1 perpendicular to L2 (axes s/2 a quarter-turn apart);
   type 2: non-regular, n even, exactly one line of straight symmetry, "passing through
           either two vertices or two edges" (it fixes two vertices or none);
   type 3: non-regular, n odd, exactly one line of straight symmetry, "passing through a
           vertex and an edge" (it fixes exactly one vertex);
   type 4: non-regular, n odd and not prime, "the number of lines of symmetry is more
           than one but less than the number of vertices". *)
Definition type0 (G : list pt) : bool := regular G.
Definition type1 (G : list pt) : bool :=
  Nat.even (length G) && negb (regular G) &&
  match mirrors G with
  | [s1; s2] => negb (through_vertex G s1) && negb (through_vertex G s2) && teq (s1 - s2) (1 # 2)
  | _ => false
  end.
Definition type2 (G : list pt) : bool :=
  Nat.even (length G) && negb (regular G) &&
  match mirrors G with
  | [s] => Nat.eqb (fixed_vertices G s) 2 || Nat.eqb (fixed_vertices G s) 0
  | _ => false
  end.
Definition type3 (G : list pt) : bool :=
  Nat.odd (length G) && negb (regular G) &&
  match mirrors G with [s] => Nat.eqb (fixed_vertices G s) 1 | _ => false end.
Definition type4 (G : list pt) : bool :=
  Nat.odd (length G) && negb (prime (length G)) && negb (regular G) &&
  Nat.ltb 1 (length (mirrors G)) && Nat.ltb (length (mirrors G)) (length G).
Definition some_type (G : list pt) : bool :=
  type0 G || type1 G || type2 G || type3 G || type4 G.

(* ------------------------------------------------------------------ CW and ACW strings *)

(* Before lemma-straight-sym: for a point m of a convex polygon G, "the vertices are labeled
   starting from the vertex next (clockwise) to m up to the previous vertex of m, as v_1,
   ..., v_n" and CW_m = (|m v_1|, ..., |m v_n|), ACW_m = (|m v_n|, ..., |m v_1|).  Here m
   is a vertex (n = k - 1).  Turns grow counter-clockwise, so the clockwise gap from m to v
   is frac(turn m - turn v).  Two vertices at angular gap g on a circle of radius R are
   2R sin(pi g) apart; sin is increasing on [0, pi/2] and sin(pi g) = sin(pi (1 - g)), so
   on one circle a distance is given by, and gives, [chord m v] = min(g, 1 - g). *)
Fixpoint insert_by (k : pt -> Q) (x : pt) (l : list pt) : list pt :=
  match l with
  | [] => [x]
  | y :: rest => if Qle_bool (k x) (k y) then x :: l else y :: insert_by k x rest
  end.
Definition sort_by (k : pt -> Q) (l : list pt) : list pt := fold_right (insert_by k) [] l.

Definition clockwise_from (G : list pt) (m : pt) : list pt :=
  sort_by (fun v => frac (turn m - turn v)) (filter (fun v => negb (peq v m)) G).
Definition chord (m v : pt) : Q :=
  let g := frac (turn m - turn v) in if Qle_bool g (1 # 2) then g else 1 - g.
Definition CW (G : list pt) (m : pt) : list Q := map (chord m) (clockwise_from G m).
Definition ACW (G : list pt) (m : pt) : list Q := rev (CW G m).

Fixpoint qlist_eqb (a b : list Q) : bool :=
  match a, b with
  | [], [] => true
  | x :: a', y :: b' => Qeq_bool x y && qlist_eqb a' b'
  | _, _ => false
  end.

(* CW_v = ACW_v. *)
Definition cw_sym (G : list pt) (v : pt) : bool := qlist_eqb (CW G v) (ACW G v).

(* obs-asymmetric-polygon (Theorem 1), conditions for 1 <= i, j <= n, i <> j (distinct
   vertices are distinct points): (1) CW_vi <> ACW_vi; (2) CW_vi <> CW_vj;
   (3) CW_vi <> ACW_vj.  Theorem 1.1: (2) ACW_vi <> ACW_vj; (3) ACW_vi <> CW_vj. *)
Definition all_pairs (G : list pt) (differ : pt -> pt -> bool) : bool :=
  forallb (fun v => forallb (fun w => peq v w || differ v w) G) G.
Definition theorem1_conditions (G : list pt) : bool :=
  forallb (fun v => negb (cw_sym G v)) G &&
  all_pairs G (fun v w => negb (qlist_eqb (CW G v) (CW G w))) &&
  all_pairs G (fun v w => negb (qlist_eqb (CW G v) (ACW G w))).
Definition theorem1_1_conditions (G : list pt) : bool :=
  forallb (fun v => negb (cw_sym G v)) G &&
  all_pairs G (fun v w => negb (qlist_eqb (ACW G v) (ACW G w))) &&
  all_pairs G (fun v w => negb (qlist_eqb (ACW G v) (CW G w))).

(* ------------------------------------------------------------------ the paper's algorithms *)

(* The loop of Check_Symmetry_Odd and Check_Symmetry_Even AS PRINTED: "while i <= n:
   compute CW_vi and ACW_vi; if CW_vi = ACW_vi then deg_sym++ else (...; i++)".  Only i
   decides whether it ends; [printed_loop fuel G i] is true iff it ends within [fuel]
   passes, the vertices v_1, ..., v_n listed in G's order. *)
Definition vertex (G : list pt) (i : nat) : pt := nth (i - 1)%nat G (Pt 0 0).
Fixpoint printed_loop (fuel : nat) (G : list pt) (i : nat) : bool :=
  match fuel with
  | O => false
  | S f => if Nat.ltb (length G) i then true
           else if cw_sym G (vertex G i) then printed_loop f G i
           else printed_loop f G (S i)
  end.

(* Check_Symmetry_Even read with i++ after every vertex (the evident reading): returns
   (st_sym, sk_sym, deg_sym).  It reports "G is straight symmetric" iff deg_sym > 0 and
   st_sym, "G is skew symmetric" iff deg_sym > 0 and sk_sym, the degree deg_sym/2, and
   "G is asymmetric" iff deg_sym = 0.  [seen] holds v_1 .. v_(i-1). *)
Fixpoint check_even_loop (G seen todo : list pt) (st sk : bool) (deg : nat)
  : bool * bool * nat :=
  match todo with
  | [] => (st, sk, deg)
  | v :: rest =>
    if cw_sym G v then check_even_loop G (seen ++ [v]) rest true sk (S deg)
    else let hits := length (filter (fun w => qlist_eqb (CW G v) (CW G w) ||
                                              qlist_eqb (CW G v) (ACW G w) ||
                                              qlist_eqb (ACW G v) (CW G w)) seen) in
         check_even_loop G (seen ++ [v]) rest st (sk || Nat.ltb 0 hits) (deg + hits)
  end.
Definition check_symmetry_even (G : list pt) : bool * bool * nat :=
  check_even_loop G [] G false false 0.
Definition even_reports_straight (G : list pt) : bool :=
  match check_symmetry_even G with (st, _, deg) => Nat.ltb 0 deg && st end.

(* Elect_Leader_Sym, n even: "Call Check_Symmetry_Even(G); if degree of symmetry of G > 1:
   Report 'Leader Election is not possible for G'", the degree being the deg_sym/2 that
   Check_Symmetry_Even reports (one reading of the ledger's entry). *)
Definition even_reported_degree (G : list pt) : nat :=
  match check_symmetry_even G with (_, _, deg) => Nat.div deg 2 end.
Definition elect_leader_sym_even_refuses (G : list pt) : bool :=
  Nat.ltb 1 (even_reported_degree G).

(* Elect_Leader_Asym: after the ordering, "i = 1; while G \ v_i is symmetric: i++;
   v_l = v_i".  It elects a vertex v with G \ v asymmetric, or none when there is no such
   vertex (the loop runs past v_n), whatever the ordering. *)
Definition remove_vertex (G : list pt) (v : pt) : list pt := filter (fun w => negb (peq w v)) G.
Definition leader_candidates (G : list pt) : list pt :=
  filter (fun v => negb (symmetric_conf (remove_vertex G v))) G.

(* The printed loop never ends once it reaches a vertex with CW = ACW. *)
Lemma printed_loop_stuck : forall G i, Nat.ltb (length G) i = false ->
  cw_sym G (vertex G i) = true -> forall fuel, printed_loop fuel G i = false.
Proof.
  intros G i Hi Hc fuel. induction fuel as [|f IH]; simpl; [reflexivity|].
  rewrite Hi, Hc. exact IH.
Qed.

Lemma printed_loop_reaches : forall G k i, (i + k <= length G)%nat ->
  cw_sym G (vertex G (i + k)) = true -> forall fuel, printed_loop fuel G i = false.
Proof.
  intros G k. induction k as [|k IH]; intros i Hle Hc fuel.
  - rewrite Nat.add_0_r in *. apply printed_loop_stuck; [apply Nat.ltb_ge; exact Hle | exact Hc].
  - destruct fuel as [|f]; simpl; [reflexivity|].
    assert (Hi : Nat.ltb (length G) i = false) by (apply Nat.ltb_ge; lia).
    rewrite Hi. destruct (cw_sym G (vertex G i)) eqn:E.
    + apply printed_loop_stuck; assumption.
    + apply IH; [lia | replace (S i + k)%nat with (i + S k)%nat by lia; exact Hc].
Qed.

(* So, as printed, Check_Symmetry_Odd and Check_Symmetry_Even never end on a polygon with
   a vertex whose CW = ACW, whatever the labelling v_1, ..., v_n (any order of G). *)
Theorem printed_loop_never_ends : forall G, existsb (cw_sym G) G = true ->
  forall fuel, printed_loop fuel G 1 = false.
Proof.
  intros G H fuel. apply existsb_exists in H. destruct H as [v [Hin Hv]].
  destruct (In_nth G v (Pt 0 0) Hin) as [k [Hk Hnth]].
  apply (printed_loop_reaches G k 1); [lia|].
  unfold vertex. replace (1 + k - 1)%nat with k by lia. rewrite Hnth. exact Hv.
Qed.

(* ------------------------------------------------------------------ Preprocess *)

(* Preprocess AS PRINTED (algorithm Preprocess(calG), G_1, ..., G_t the polygons):
     i = 1; while i <= t: if G_i is odd { j = 1; while j <= t: if j <> i & G_j is odd
       { compute G_ij; if G_ij is type 4: replace G_i by G_ij, else j++ } else j++ }
     else i++.
   Only these counters decide whether it ends.  [poly Gs k] is G_k (k from 1), and
   [pre_step] one pass of either loop (None: it has ended). *)
Inductive pstate := Outer (i : nat) | Inner (i j : nat).
Definition poly (Gs : list (list pt)) (k : nat) : list pt := nth (k - 1) Gs [].
Fixpoint set_nth (Gs : list (list pt)) (k : nat) (G : list pt) : list (list pt) :=
  match Gs, k with
  | [], _ => []
  | _ :: rest, O => G :: rest
  | H :: rest, S k' => H :: set_nth rest k' G
  end.
Definition pre_step (Gs : list (list pt)) (st : pstate) : option (list (list pt) * pstate) :=
  match st with
  | Outer i => if Nat.ltb (length Gs) i then None
               else if Nat.odd (length (poly Gs i)) then Some (Gs, Inner i 1)
               else Some (Gs, Outer (S i))
  | Inner i j => if Nat.ltb (length Gs) j then Some (Gs, Outer i)
                 else if negb (Nat.eqb j i) && Nat.odd (length (poly Gs j)) then
                   let Gij := merged (poly Gs i) (poly Gs j) in
                   if type4 Gij then Some (set_nth Gs (i - 1) Gij, Inner i j)
                   else Some (Gs, Inner i (S j))
                 else Some (Gs, Inner i (S j))
  end.
(* [preprocess_printed fuel Gs st] is true iff the printed loops end within [fuel] passes. *)
Fixpoint preprocess_printed (fuel : nat) (Gs : list (list pt)) (st : pstate) : bool :=
  match fuel with
  | O => false
  | S f => match pre_step Gs st with
           | None => true
           | Some (Gs', st') => preprocess_printed f Gs' st'
           end
  end.

Lemma set_nth_length : forall Gs k G, length (set_nth Gs k G) = length Gs.
Proof. induction Gs as [|H rest IH]; intros [|k] G; simpl; auto. Qed.

Lemma set_nth_nth : forall Gs k G, (k < length Gs)%nat -> nth k (set_nth Gs k G) [] = G.
Proof.
  induction Gs as [|H rest IH]; intros [|k] G Hk; simpl in *; try lia; auto.
  apply IH. lia.
Qed.

Definition pindex (st : pstate) : nat := match st with Outer i => i | Inner i _ => i end.
(* The invariant: i is a polygon's index and G_i is odd. *)
Definition pinv (Gs : list (list pt)) (st : pstate) : Prop :=
  (1 <= pindex st <= length Gs)%nat /\ Nat.odd (length (poly Gs (pindex st))) = true.

Lemma type4_odd : forall G, type4 G = true -> Nat.odd (length G) = true.
Proof. intros G H. unfold type4 in H. now repeat rewrite andb_true_iff in H. Qed.

(* With G_i odd nothing increments i: G_i is replaced only by a type 4 polygon, odd. *)
Lemma pre_step_keeps : forall Gs st, pinv Gs st ->
  exists Gs' st', pre_step Gs st = Some (Gs', st') /\ pinv Gs' st'.
Proof.
  intros Gs [i|i j] [Hi Ho]; simpl in Hi, Ho; simpl.
  - rewrite (proj2 (Nat.ltb_ge (length Gs) i) ltac:(lia)), Ho. eexists; eexists; split; [reflexivity|].
    split; simpl; assumption.
  - destruct (Nat.ltb (length Gs) j).
    + eexists; eexists; split; [reflexivity|]. split; simpl; assumption.
    + destruct (negb (Nat.eqb j i) && Nat.odd (length (poly Gs j))).
      * destruct (type4 (merged (poly Gs i) (poly Gs j))) eqn:T.
        -- eexists; eexists; split; [reflexivity|]. split; simpl.
           ++ rewrite set_nth_length. exact Hi.
           ++ unfold poly at 1. rewrite set_nth_nth by lia. apply type4_odd. exact T.
        -- eexists; eexists; split; [reflexivity|]. split; simpl; assumption.
      * eexists; eexists; split; [reflexivity|]. split; simpl; assumption.
Qed.

Lemma preprocess_stuck : forall fuel Gs st, pinv Gs st -> preprocess_printed fuel Gs st = false.
Proof.
  induction fuel as [|f IH]; intros Gs st H; simpl; [reflexivity|].
  destruct (pre_step_keeps Gs st H) as [Gs' [st' [E H']]]. rewrite E. apply IH. exact H'.
Qed.

(* So, as printed, Preprocess never ends once calG holds an odd polygon, whatever the
   order of the polygons: i reaches the first odd one and stays there. *)
Theorem preprocess_printed_never_ends : forall Gs,
  existsb (fun G => Nat.odd (length G)) Gs = true ->
  forall fuel, preprocess_printed fuel Gs (Outer 1) = false.
Proof.
  intros Gs H. apply existsb_exists in H. destruct H as [G [Hin Hodd]].
  destruct (In_nth Gs G [] Hin) as [m [Hm Hnth]].
  assert (Reach : forall k i, (i + k = S m)%nat -> (1 <= i)%nat ->
            forall fuel, preprocess_printed fuel Gs (Outer i) = false).
  { induction k as [|k IHk]; intros i Hik H1 fuel.
    - apply preprocess_stuck. split; simpl; [lia|]. unfold poly.
      replace (i - 1)%nat with m by lia. rewrite Hnth. exact Hodd.
    - destruct fuel as [|f]; simpl; [reflexivity|].
      rewrite (proj2 (Nat.ltb_ge (length Gs) i) ltac:(lia)).
      destruct (Nat.odd (length (poly Gs i))) eqn:O.
      + apply preprocess_stuck. split; simpl; [lia | exact O].
      + apply IHk; lia. }
  intros fuel. apply (Reach m 1%nat); lia.
Qed.

(* ------------------------------------------------------------------ not orderable: a theorem *)

Lemma pt_eqb_refl : forall p, pt_eqb p p = true.
Proof.
  intros [[a b] [c d]]. unfold pt_eqb, q_eqb. simpl. now rewrite !Z.eqb_refl, !Pos.eqb_refl.
Qed.

Lemma map_fixed : forall (f : pt -> pt) l, map f l = l -> forall x, In x l -> f x = x.
Proof.
  intros f l. induction l as [|a l IH]; simpl; intros E x H; [contradiction|].
  injection E as Ea El. destruct H as [<-|H]; [exact Ea | exact (IH El x H)].
Qed.

(* ------------------------------------------------------------------ canonical forms *)

(* [canon] gives one term per point ([canon_peq]: one point, one canonical form). *)
Lemma divides_transfer : forall n d n' d', (0 < d)%Z -> (0 < d')%Z ->
  (n * d' = n' * d)%Z -> (d | n)%Z -> (d' | n')%Z.
Proof.
  intros n d n' d' Hd Hd' H [k Hk]. exists k. subst n.
  apply (Z.mul_reg_r _ _ d); [lia|]. rewrite <- H. ring.
Qed.

Lemma integral_Qeq : forall q q', q == q' -> integral q = integral q'.
Proof.
  intros [n d] [n' d'] H. unfold Qeq in H; simpl in H. unfold integral; simpl.
  destruct (Z.eqb_spec (n mod Z.pos d) 0) as [E|E];
  destruct (Z.eqb_spec (n' mod Z.pos d') 0) as [E'|E']; try reflexivity; exfalso.
  - apply E'. apply Z.mod_divide; [lia|]. apply Z.mod_divide in E; [|lia].
    apply (divides_transfer n (Z.pos d)); auto; lia.
  - apply E. apply Z.mod_divide; [lia|]. apply Z.mod_divide in E'; [|lia].
    apply (divides_transfer n' (Z.pos d')); auto; lia.
Qed.

Lemma frac_teq : forall t t', teq t t' = true -> frac t == frac t'.
Proof.
  intros [a b] [c d] H. unfold teq, integral in H. simpl in H.
  apply Z.eqb_eq in H. apply Z.mod_divide in H; [|lia]. destruct H as [k Hk].
  unfold frac, Qeq; simpl.
  pose proof (Z.div_mod a (Z.pos b) ltac:(lia)) as Ha.
  pose proof (Z.div_mod c (Z.pos d) ltac:(lia)) as Hc.
  pose proof (Z.mod_pos_bound a (Z.pos b) ltac:(lia)) as Ba.
  pose proof (Z.mod_pos_bound c (Z.pos d) ltac:(lia)) as Bc.
  set (u := (a mod Z.pos b)%Z) in *. set (w := (c mod Z.pos d)%Z) in *.
  set (q1 := (a / Z.pos b)%Z) in *. set (q2 := (c / Z.pos d)%Z) in *.
  assert (M : (u * Z.pos d - w * Z.pos b = (k - q1 + q2) * (Z.pos b * Z.pos d))%Z).
  { rewrite Pos2Z.inj_mul in Hk. nia. }
  assert (X1 : (0 <= u * Z.pos d < Z.pos b * Z.pos d)%Z) by nia.
  assert (X2 : (0 <= w * Z.pos b < Z.pos b * Z.pos d)%Z) by nia.
  revert M X1 X2. generalize (Z.pos b * Z.pos d)%Z (u * Z.pos d)%Z (w * Z.pos b)%Z
    (k - q1 + q2)%Z. intros P X Y m M X1 X2.
  assert (m = 0)%Z.
  { destruct (Z.lt_trichotomy m 0) as [L|[L|L]]; [|exact L|]; exfalso.
    - assert (m * P <= - P)%Z by nia. lia.
    - assert (P <= m * P)%Z by nia. lia. }
  subst m. lia.
Qed.

Lemma canon_peq : forall x y, peq x y = true -> canon x = canon y.
Proof.
  intros [rx tx] [ry ty] H. unfold peq in H; simpl in H.
  apply andb_true_iff in H. destruct H as [Hr Ht]. apply Qeq_bool_iff in Hr.
  unfold canon; cbn [r2 turn].
  destruct (Qeq_bool rx 0) eqn:Ex; destruct (Qeq_bool ry 0) eqn:Ey; try reflexivity.
  - apply Qeq_bool_iff in Ex. apply Qeq_bool_neq in Ey. exfalso. apply Ey. rewrite <- Hr. exact Ex.
  - apply Qeq_bool_iff in Ey. apply Qeq_bool_neq in Ex. exfalso. apply Ex. rewrite Hr. exact Ey.
  - f_equal; apply Qred_complete; [exact Hr | apply frac_teq; exact Ht].
Qed.

Lemma pt_eqb_eq : forall p q, pt_eqb p q = true -> p = q.
Proof.
  intros [[a b] [c d]] [[a' b'] [c' d']] H. unfold pt_eqb, q_eqb in H; simpl in H.
  repeat rewrite andb_true_iff in H.
  destruct H as [[H1 H2] [H3 H4]].
  apply Z.eqb_eq in H1, H3. apply Pos.eqb_eq in H2, H4. subst. reflexivity.
Qed.

Lemma frac_frac : forall t, frac (frac t) == frac t.
Proof. intros [a b]. unfold frac; simpl. rewrite Z.mod_mod by lia. reflexivity. Qed.

Lemma canon_canon : forall q, canon (canon q) = canon q.
Proof.
  intros [r t]. destruct (Qeq_bool r 0) eqn:E.
  - assert (H : canon (Pt r t) = Pt 0 0) by (unfold canon; cbn [r2]; rewrite E; reflexivity).
    rewrite H. reflexivity.
  - assert (H : canon (Pt r t) = Pt (Qred r) (Qred (frac t)))
      by (unfold canon; cbn [r2]; rewrite E; reflexivity).
    rewrite H. unfold canon at 1; cbn [r2 turn].
    assert (Hr : Qeq_bool (Qred r) 0 = false).
    { apply Qeq_bool_neq in E. destruct (Qeq_bool (Qred r) 0) eqn:F; [|reflexivity].
      exfalso. apply E. apply Qeq_bool_iff in F. rewrite <- (Qred_correct r). exact F. }
    rewrite Hr, (Qred_complete _ _ (Qred_correct r)). f_equal. apply Qred_complete.
    rewrite <- (frac_frac t) at 2. apply frac_teq.
    unfold teq. rewrite (integral_Qeq _ 0); [reflexivity|].
    rewrite Qred_correct. ring.
Qed.

(* ------------------------------------------------------------------ not orderable: the theorem *)

Lemma integral_opp : forall q, integral (- q) = integral q.
Proof.
  intros [n d]. unfold integral; simpl.
  destruct (Z.eqb_spec ((- n) mod Z.pos d) 0) as [E|E];
  destruct (Z.eqb_spec (n mod Z.pos d) 0) as [E'|E']; try reflexivity; exfalso.
  - apply E'. apply Z.mod_divide; [lia|]. apply Z.mod_divide in E; [|lia].
    apply Z.divide_opp_r in E. now rewrite Z.opp_involutive in E.
  - apply E. apply Z.mod_divide; [lia|]. apply Z.mod_divide in E'; [|lia].
    now apply Z.divide_opp_r.
Qed.

(* An isometry about C maps one point to one point. *)
Lemma act_peq : forall g x y, peq x y = true -> peq (act g x) (act g y) = true.
Proof.
  intros [a|s'] [rx tx] [ry ty] H; unfold peq in *; simpl in *;
  apply andb_true_iff in H; destruct H as [Hr Ht]; rewrite Hr; simpl;
  destruct (Qeq_bool rx 0); simpl in *; auto; unfold teq in *.
  - rewrite (integral_Qeq _ (tx - ty)); [exact Ht | ring].
  - rewrite (integral_Qeq _ (- (tx - ty))); [rewrite integral_opp; exact Ht | ring].
Qed.

Lemma canonical_in : forall P p, canonical P = true -> In p P -> canon p = p.
Proof.
  intros P p H Hp. unfold canonical in H. rewrite forallb_forall in H.
  exact (pt_eqb_eq _ _ (H p Hp)).
Qed.

(* lemma-sym-ord's argument, proved: a symmetry g of P that moves a point of P leaves no
   ordering invariant, since describing P in the coordinates moved by g gives P again.
   P is written canonically, so "moves" (the canonical image is another term) means
   "maps to another point" ([canon_peq]). *)
Theorem not_orderable : forall P g p, canonical P = true ->
  same_set (map (image g) P) P = true -> In p P -> pt_eqb (image g p) p = false ->
  ~ orderable P.
Proof.
  intros P g p Hcan Hset Hp Hmove [order [Hsame [Hcov Hall]]].
  pose proof (Hsame _ _ Hset) as E. rewrite Hcov in E.
  pose proof (map_fixed _ _ E) as Fix.
  pose proof (Hall p Hp) as Hm. apply existsb_exists in Hm. destruct Hm as [z [Hz Hpz]].
  assert (Hi : image g p = z).
  { unfold image. rewrite (canon_peq _ _ (act_peq g p z Hpz)). exact (Fix z Hz). }
  assert (Hzc : canon z = z) by (rewrite <- (Fix z Hz); unfold image; apply canon_canon).
  assert (Hpzc : p = z).
  { rewrite <- (canonical_in P p Hcan Hp), <- Hzc. apply canon_peq. exact Hpz. }
  rewrite Hi, <- Hpzc, pt_eqb_refl in Hmove. discriminate.
Qed.

(* The same from a search over the candidates: no trust in (T2) is needed here, only that
   the candidate found maps P onto itself (checked) and moves a point of P (checked). *)
Definition not_orderable_dec (P : list pt) : bool :=
  existsb (fun g => same_set (map (image g) P) P &&
                    existsb (fun p => negb (pt_eqb (image g p) p)) P) (candidates P).

Theorem not_orderable_by_candidates : forall P, canonical P = true ->
  not_orderable_dec P = true -> ~ orderable P.
Proof.
  intros P Hcan H. unfold not_orderable_dec in H. apply existsb_exists in H.
  destruct H as [g [_ H]]. apply andb_true_iff in H. destruct H as [Hset Hmoves].
  apply existsb_exists in Hmoves. destruct Hmoves as [p [Hp Hm]].
  apply (not_orderable P g p Hcan Hset Hp).
  destruct (pt_eqb (image g p) p); [discriminate | reflexivity].
Qed.

(* ------------------------------------------------------------------ orderable: a theorem *)

(* def-orderable-set met: [orderable_of_only_identity] below.  First [peq] is shown an
   equivalence and [canon] its canonical form; then (T2) for the isometries about C
   ([candidates_complete]); then the ordering [order_by_images]. *)

Lemma integral_divide : forall q, integral q = true <-> (Zpos (Qden q) | Qnum q)%Z.
Proof.
  intros [n d]. unfold integral; simpl. rewrite Z.eqb_eq.
  split; intro H; apply Z.mod_divide; (lia || exact H).
Qed.

Lemma integral_add : forall x y, integral x = true -> integral y = true ->
  integral (x + y) = true.
Proof.
  intros [a b] [c d] Hx Hy. apply integral_divide in Hx, Hy. apply integral_divide.
  simpl in *. destruct Hx as [k Hk]. destruct Hy as [m Hm]. exists (k + m)%Z.
  rewrite Pos2Z.inj_mul. subst. ring.
Qed.

Lemma teq_Qeq : forall a b, a == b -> teq a b = true.
Proof. intros a b H. unfold teq. rewrite (integral_Qeq _ 0); [reflexivity|]. rewrite H. ring. Qed.

Lemma teq_sym : forall a b, teq a b = true -> teq b a = true.
Proof.
  intros a b H. unfold teq in *. rewrite (integral_Qeq _ (- (a - b))) by ring.
  rewrite integral_opp. exact H.
Qed.

Lemma teq_trans : forall a b c, teq a b = true -> teq b c = true -> teq a c = true.
Proof.
  intros a b c H1 H2. unfold teq in *. rewrite (integral_Qeq _ ((a - b) + (b - c))) by ring.
  apply integral_add; assumption.
Qed.

Lemma Qeq_bool_compat : forall x y z, x == y -> Qeq_bool x z = Qeq_bool y z.
Proof.
  intros x y z H. destruct (Qeq_bool x z) eqn:E; destruct (Qeq_bool y z) eqn:F;
  try reflexivity; exfalso.
  - apply Qeq_bool_iff in E. apply Qeq_bool_neq in F. apply F. rewrite <- H. exact E.
  - apply Qeq_bool_iff in F. apply Qeq_bool_neq in E. apply E. rewrite H. exact F.
Qed.

(* [peq] is an equivalence. *)
Lemma peq_refl : forall x, peq x x = true.
Proof.
  intros x. unfold peq. rewrite Qeq_bool_refl, (teq_Qeq _ _ (Qeq_refl _)), orb_true_r.
  reflexivity.
Qed.

Lemma peq_sym : forall x y, peq x y = true -> peq y x = true.
Proof.
  intros x y H. unfold peq in *. apply andb_true_iff in H. destruct H as [Hr Ht].
  apply Qeq_bool_iff in Hr. apply andb_true_iff. split.
  - apply Qeq_bool_iff. symmetry. exact Hr.
  - rewrite <- (Qeq_bool_compat _ _ 0 Hr). apply orb_true_iff in Ht. apply orb_true_iff.
    destruct Ht as [H0|H0]; [left; exact H0 | right; apply teq_sym; exact H0].
Qed.

Lemma peq_trans : forall x y z, peq x y = true -> peq y z = true -> peq x z = true.
Proof.
  intros x y z H1 H2. unfold peq in *. apply andb_true_iff in H1, H2.
  destruct H1 as [R1 T1]. destruct H2 as [R2 T2]. apply Qeq_bool_iff in R1, R2.
  apply andb_true_iff. split; [apply Qeq_bool_iff; rewrite R1; exact R2|].
  destruct (Qeq_bool (r2 x) 0) eqn:E; [reflexivity|]. simpl in *.
  rewrite <- (Qeq_bool_compat _ _ 0 R1), E in T2. simpl in T2.
  exact (teq_trans _ _ _ T1 T2).
Qed.

Lemma frac_teq_self : forall t, teq (frac t) t = true.
Proof.
  intros [a b]. unfold teq. apply integral_divide. unfold frac. simpl.
  pose proof (Z.div_mod a (Z.pos b) ltac:(lia)) as Ha.
  remember (a / Z.pos b)%Z as q. remember (a mod Z.pos b)%Z as m.
  exists (- q)%Z. rewrite Pos2Z.inj_mul. rewrite Ha at 1. ring.
Qed.

Lemma peq_canon : forall x, peq (canon x) x = true.
Proof.
  intros [r t]. unfold canon. cbn [r2 turn]. destruct (Qeq_bool r 0) eqn:E.
  - apply Qeq_bool_iff in E. unfold peq. cbn [r2 turn]. apply andb_true_iff.
    split; [apply Qeq_bool_iff; rewrite E; reflexivity | reflexivity].
  - unfold peq. cbn [r2 turn]. apply andb_true_iff. split; [apply Qeq_bool_iff; apply Qred_correct|].
    apply orb_true_iff. right. unfold teq.
    rewrite (integral_Qeq _ (frac t - t)) by (rewrite Qred_correct; reflexivity).
    exact (frac_teq_self t).
Qed.

Lemma peq_canon_iff : forall x y, peq x y = true <-> canon x = canon y.
Proof.
  intros x y. split; [apply canon_peq|]. intros E.
  apply (peq_trans _ (canon x)); [apply peq_sym, peq_canon|].
  rewrite E. apply peq_canon.
Qed.

Lemma mem_iff : forall x L, mem x L = true <-> exists w, In w L /\ canon x = canon w.
Proof.
  intros x L. unfold mem. rewrite existsb_exists. split; intros [w [H1 H2]]; exists w;
  split; try exact H1; apply peq_canon_iff; exact H2.
Qed.

Lemma canon_image : forall g x, canon (image g x) = image g x.
Proof. intros g x. apply canon_canon. Qed.

Lemma image_canon : forall g x, image g (canon x) = image g x.
Proof. intros g x. apply canon_peq, act_peq, peq_canon. Qed.

Lemma r2_act : forall g x, r2 (act g x) = r2 x.
Proof. intros [a|s] x; reflexivity. Qed.

(* The inverse of an isometry about C, and composition (first g, then h). *)
Definition inv (g : iso) : iso := match g with Rot a => Rot (- a) | Mirror s => Mirror s end.
Definition comp (g h : iso) : iso :=
  match g, h with
  | Rot a, Rot b => Rot (a + b)
  | Rot a, Mirror s => Mirror (s - a)
  | Mirror s, Rot b => Mirror (s + b)
  | Mirror s, Mirror s' => Rot (s' - s)
  end.

Lemma peq_same_r2 : forall r t t', t == t' -> peq (Pt r t) (Pt r t') = true.
Proof.
  intros r t t' H. unfold peq. cbn [r2 turn]. rewrite Qeq_bool_refl, (teq_Qeq _ _ H), orb_true_r.
  reflexivity.
Qed.

Lemma act_inv_l : forall g x, peq (act (inv g) (act g x)) x = true.
Proof. intros [a|s] [r t]; apply peq_same_r2; simpl; ring. Qed.

Lemma act_inv_r : forall g x, peq (act g (act (inv g) x)) x = true.
Proof. intros [a|s] [r t]; apply peq_same_r2; simpl; ring. Qed.

Lemma act_comp : forall g h x, peq (act (comp g h) x) (act h (act g x)) = true.
Proof. intros [a|s] [b|s'] [r t]; apply peq_same_r2; simpl; ring. Qed.

Lemma anchor_spec : forall P a, anchor P = Some a -> In a P /\ Qlt_bool 0 (r2 a) = true.
Proof.
  induction P as [|p P IH]; simpl; intros a H; [discriminate|].
  destruct (Qlt_bool 0 (r2 p)) eqn:E.
  - injection H as <-. split; [left; reflexivity | exact E].
  - destruct (IH a H) as [H1 H2]. split; [right; exact H1 | exact H2].
Qed.

Lemma Qlt_bool_neq : forall x, Qlt_bool 0 x = true -> Qeq_bool x 0 = false.
Proof.
  intros x H. unfold Qlt_bool in H. apply negb_true_iff in H.
  destruct (Qeq_bool x 0) eqn:E; [|reflexivity].
  apply Qeq_bool_iff in E.
  assert (L : Qle_bool x 0 = true) by (apply Qle_bool_iff; rewrite E; apply Qle_refl).
  congruence.
Qed.

(* The isometry about C taking a (off C) to q, of the kind of h, acts as h does when h
   takes a to q: an isometry about C is determined by its kind and the image of one
   point off C. *)
Lemma cand_like : forall a q h, Qeq_bool (r2 a) 0 = false -> peq (act h a) q = true ->
  exists c, In c [Rot (turn q - turn a); Mirror (turn q + turn a)] /\
            forall x, peq (act c x) (act h x) = true.
Proof.
  intros a q h Ha H. unfold peq in H. rewrite r2_act, Ha in H. simpl in H.
  apply andb_true_iff in H. destruct H as [_ T].
  destruct h as [b|s]; simpl in T.
  - exists (Rot (turn q - turn a)). split; [left; reflexivity|]. intros [r t].
    unfold peq; cbn [act r2 turn]. rewrite Qeq_bool_refl.
    apply orb_true_iff. right. unfold teq in *.
    rewrite (integral_Qeq _ (- (turn a + b - turn q))) by ring. rewrite integral_opp. exact T.
  - exists (Mirror (turn q + turn a)). split; [right; left; reflexivity|]. intros [r t].
    unfold peq; cbn [act r2 turn]. rewrite Qeq_bool_refl.
    apply orb_true_iff. right. unfold teq in *.
    rewrite (integral_Qeq _ (- (s - turn a - turn q))) by ring. rewrite integral_opp. exact T.
Qed.

(* (T2) as a theorem over this representation: every isometry about C mapping P into
   itself acts on every point as one of [candidates P] does. *)
Theorem candidates_complete : forall P h a, anchor P = Some a -> is_symmetry h P = true ->
  exists c, In c (candidates P) /\ forall x, peq (act c x) (act h x) = true.
Proof.
  intros P h a Ha Hs. destruct (anchor_spec P a Ha) as [HaP Hpos].
  unfold is_symmetry in Hs. rewrite forallb_forall in Hs.
  pose proof (Hs a HaP) as Hm. apply existsb_exists in Hm. destruct Hm as [q [Hq Hpq]].
  pose proof (Qlt_bool_neq _ Hpos) as Hne.
  destruct (cand_like a q h Hne Hpq) as [c [Hc Hl]]. exists c. split; [|exact Hl].
  unfold candidates. rewrite Ha. apply in_flat_map. exists q. split; [exact Hq|].
  assert (R : Qeq_bool (r2 q) (r2 a) = true).
  { unfold peq in Hpq. apply andb_true_iff in Hpq. destruct Hpq as [R _].
    rewrite r2_act in R. apply Qeq_bool_iff in R. apply Qeq_bool_iff. symmetry. exact R. }
  rewrite R. exact Hc.
Qed.

(* The check: P has a point off C, and every candidate mapping P onto itself fixes each
   point of P (the identity on P is its only symmetry about C). *)
Definition only_identity (P : list pt) : bool :=
  match anchor P with
  | None => false
  | Some _ => forallb (fun c => negb (is_symmetry c P) || forallb (fun p => peq (act c p) p) P)
                      (candidates P)
  end.

Lemma mem_peq : forall x y L, peq x y = true -> mem y L = true -> mem x L = true.
Proof.
  intros x y L H1 H2. apply mem_iff in H2. apply mem_iff. destruct H2 as [w [Hw E]].
  exists w. split; [exact Hw|]. rewrite <- E. apply peq_canon_iff. exact H1.
Qed.

(* Two isometries about C mapping P onto one set agree on P, when the identity is P's
   only symmetry. *)
Lemma images_agree : forall P g g', only_identity P = true ->
  (forall p, In p P -> exists p', In p' P /\ image g p = image g' p') ->
  forall p, In p P -> image g p = image g' p.
Proof.
  intros P g g' Hid Hcov.
  set (h := comp g (inv g')).
  assert (Hh : forall p, In p P -> exists p', In p' P /\ peq (act h p) p' = true).
  { intros p Hp. destruct (Hcov p Hp) as [p' [Hp' E]]. exists p'. split; [exact Hp'|].
    apply (peq_trans _ _ _ (act_comp g (inv g') p)).
    apply (peq_trans _ (act (inv g') (act g' p'))); [|apply act_inv_l].
    apply act_peq. apply peq_canon_iff. exact E. }
  assert (Hs : is_symmetry h P = true).
  { unfold is_symmetry. apply forallb_forall. intros p Hp. destruct (Hh p Hp) as [p' [Hp' E]].
    apply existsb_exists. exists p'. split; assumption. }
  unfold only_identity in Hid. destruct (anchor P) as [a|] eqn:Ha; [|discriminate].
  destruct (candidates_complete P h a Ha Hs) as [c [Hc Hl]].
  rewrite forallb_forall in Hid. pose proof (Hid c Hc) as Hc'.
  assert (Hcs : is_symmetry c P = true).
  { unfold is_symmetry in *. rewrite forallb_forall in *. intros p Hp.
    apply (mem_peq _ (act h p)); [apply Hl | apply Hs; exact Hp]. }
  rewrite Hcs in Hc'. simpl in Hc'. rewrite forallb_forall in Hc'.
  intros p Hp. unfold image. apply canon_peq.
  assert (F : peq (act h p) p = true).
  { apply (peq_trans _ (act c p)); [apply peq_sym, Hl | apply Hc'; exact Hp]. }
  apply (peq_trans _ (act g' (act (inv g') (act g p)))); [apply peq_sym, act_inv_r|].
  apply act_peq. apply (peq_trans _ (act h p)); [apply peq_sym, act_comp | exact F].
Qed.

Lemma same_set_iff : forall L M, same_set L M = true <->
  (forall x, In x L -> exists y, In y M /\ canon x = canon y) /\
  (forall y, In y M -> exists x, In x L /\ canon y = canon x).
Proof.
  intros L M. unfold same_set. rewrite andb_true_iff, !forallb_forall.
  split; intros [H1 H2]; split; intros x Hx.
  - apply mem_iff. exact (H1 x Hx).
  - apply mem_iff. exact (H2 x Hx).
  - apply mem_iff. exact (H1 x Hx).
  - apply mem_iff. exact (H2 x Hx).
Qed.

Lemma same_set_refl : forall L, same_set L L = true.
Proof.
  intros L. apply same_set_iff. split; intros x Hx; exists x; split; auto.
Qed.

Lemma same_set_sym : forall L M, same_set L M = true -> same_set M L = true.
Proof. intros L M H. apply same_set_iff in H. apply same_set_iff. tauto. Qed.

Lemma same_set_trans : forall L M N, same_set L M = true -> same_set M N = true ->
  same_set L N = true.
Proof.
  intros L M N H1 H2. apply same_set_iff in H1, H2. apply same_set_iff.
  destruct H1 as [A1 B1]. destruct H2 as [A2 B2]. split.
  - intros x Hx. destruct (A1 x Hx) as [y [Hy E]]. destruct (A2 y Hy) as [z [Hz E']].
    exists z. split; [exact Hz | congruence].
  - intros z Hz. destruct (B2 z Hz) as [y [Hy E]]. destruct (B1 y Hy) as [x [Hx E']].
    exists x. split; [exact Hx | congruence].
Qed.

(* The isometries about C taking a to a point of A. *)
Definition cands_to (a : pt) (A : list pt) : list iso :=
  flat_map (fun q => [Rot (turn q - turn a); Mirror (turn q + turn a)]) A.
Definition find_iso (P : list pt) (a : pt) (A : list pt) : option iso :=
  find (fun g => same_set (map (image g) P) A) (cands_to a A).

Lemma find_iso_some : forall P a A g, anchor P = Some a ->
  same_set (map (image g) P) A = true -> exists g', find_iso P a A = Some g'.
Proof.
  intros P a A g Ha H. destruct (find_iso P a A) as [g'|] eqn:F; [exists g'; reflexivity|].
  exfalso. destruct (anchor_spec P a Ha) as [HaP Hpos].
  pose proof H as H'. apply same_set_iff in H'. destruct H' as [H1 _].
  destruct (H1 (image g a) (in_map _ _ _ HaP)) as [q [Hq E]].
  rewrite canon_image in E. unfold image in E. apply peq_canon_iff in E.
  destruct (cand_like a q g (Qlt_bool_neq _ Hpos) E) as [c [Hc Hl]].
  assert (Hin : In c (cands_to a A)) by (apply in_flat_map; exists q; split; assumption).
  pose proof (find_none _ _ F c Hin) as N. simpl in N.
  replace (map (image c) P) with (map (image g) P) in N; [congruence|].
  apply map_ext. intros x. unfold image. symmetry. apply canon_peq. apply Hl.
Qed.

Lemma agree_on_set : forall P g g' A, only_identity P = true ->
  same_set (map (image g) P) A = true -> same_set (map (image g') P) A = true ->
  map (image g) P = map (image g') P.
Proof.
  intros P g g' A Hid H1 H2. apply map_ext_in. apply (images_agree P g g' Hid).
  intros p Hp. pose proof (same_set_trans _ _ _ H1 (same_set_sym _ _ H2)) as H.
  apply same_set_iff in H. destruct H as [H _].
  destruct (H (image g p) (in_map _ _ _ Hp)) as [y [Hy E]].
  apply in_map_iff in Hy. destruct Hy as [p' [<- Hp']]. exists p'. split; [exact Hp'|].
  rewrite !canon_image in E. exact E.
Qed.

(* The ordering: a set that some isometry g about C maps P onto is listed as the images
   of P's points under g, in P's order (by [images_agree] it does not matter which g);
   any other set is given the empty list. *)
Definition order_by_images (P : list pt) (A : list pt) : list pt :=
  match anchor P with
  | None => []
  | Some a => match find_iso P a A with Some g => map (image g) P | None => [] end
  end.

Lemma image_id : forall p, image (Rot 0) p = canon p.
Proof. intros [r t]. unfold image. apply canon_peq. apply peq_same_r2. simpl. ring. Qed.

Lemma order_by_images_orders : forall P, only_identity P = true ->
  (forall A B, same_set A B = true -> order_by_images P A = order_by_images P B) /\
  (forall g, order_by_images P (map (image g) P) = map (image g) (order_by_images P P)) /\
  order_by_images P P = map canon P.
Proof.
  intros P Hid. destruct (anchor P) as [a|] eqn:Ha;
    [| unfold only_identity in Hid; rewrite Ha in Hid; discriminate].
  assert (Hself : map (image (Rot 0)) P = map canon P) by (apply map_ext; exact image_id).
  assert (HP : order_by_images P P = map canon P).
  { assert (S0 : same_set (map (image (Rot 0)) P) P = true).
    { rewrite Hself. apply same_set_iff. split; intros x Hx.
      - apply in_map_iff in Hx. destruct Hx as [p [<- Hp]]. exists p.
        split; [exact Hp | apply canon_canon].
      - exists (canon x). split; [apply in_map; exact Hx | symmetry; apply canon_canon]. }
    destruct (find_iso_some P a P _ Ha S0) as [g0 F]. unfold order_by_images.
    rewrite Ha, F. rewrite <- Hself. apply (agree_on_set P g0 (Rot 0) P Hid); [|exact S0].
    unfold find_iso in F. apply find_some in F. exact (proj2 F). }
  split; [|split; [|exact HP]].
  - intros A B H. unfold order_by_images. rewrite Ha.
    destruct (find_iso P a A) as [g|] eqn:FA; destruct (find_iso P a B) as [g'|] eqn:FB.
    + unfold find_iso in FA, FB. apply find_some in FA, FB.
      apply (agree_on_set P g g' A Hid); [exact (proj2 FA)|].
      exact (same_set_trans _ _ _ (proj2 FB) (same_set_sym _ _ H)).
    + unfold find_iso in FA. apply find_some in FA.
      destruct (find_iso_some P a B g Ha (same_set_trans _ _ _ (proj2 FA) H)) as [x E].
      congruence.
    + unfold find_iso in FB. apply find_some in FB.
      destruct (find_iso_some P a A g' Ha
                  (same_set_trans _ _ _ (proj2 FB) (same_set_sym _ _ H))) as [x E].
      congruence.
    + reflexivity.
  - intros g. rewrite HP, map_map.
    replace (map (fun x => image g (canon x)) P) with (map (image g) P)
      by (apply map_ext; intros x; symmetry; apply image_canon).
    destruct (find_iso_some P a (map (image g) P) g Ha (same_set_refl _)) as [g1 F].
    unfold order_by_images. rewrite Ha, F.
    apply (agree_on_set P g1 g (map (image g) P) Hid); [|apply same_set_refl].
    unfold find_iso in F. apply find_some in F. exact (proj2 F).
Qed.

(* def-orderable-set, when the identity on P is its only symmetry about C: P is
   orderable.  With [candidates_complete] ((T2) proved) the check [only_identity P]
   is decided by computation over the finite list of candidates.  [sec_centred P] is not
   used by the proof: it is what makes the isometries about C all of P's symmetries (T1),
   so that [orderable P] is the paper's notion (for an off-centre set it is not: the
   library's header). *)
Theorem orderable_of_only_identity : forall P, sec_centred P = true ->
  only_identity P = true -> orderable P.
Proof.
  intros P _ Hid. destruct (order_by_images_orders P Hid) as [H1 [H2 H3]].
  exists (order_by_images P). split; [exact H1|]. split; [exact H2|].
  intros p Hp. rewrite H3. apply mem_iff. exists (canon p).
  split; [apply in_map; exact Hp | symmetry; apply canon_canon].
Qed.

(* Leader election (the abstract: "the first robot in the ordering becomes the leader
   ... each robot, characterized by its location, agrees on the same ordering"; MakeAsym
   elects one robot v_l and moves it): an algorithm reading the set designates a robot
   of P, the same one whatever the coordinates among the isometries about C (as for
   def-orderable-set).  Under the same condition P has a leader: the first robot of
   [order_by_images]. *)
Definition electable (P : list pt) : Prop :=
  exists elect : list pt -> pt,
    (forall A B, same_set A B = true -> elect A = elect B) /\
    (forall g, elect (map (image g) P) = image g (elect P)) /\
    mem (elect P) P = true.

Theorem electable_of_only_identity : forall P, sec_centred P = true ->
  only_identity P = true -> electable P.
Proof.
  intros P _ Hid. destruct (order_by_images_orders P Hid) as [H1 [H2 H3]].
  destruct P as [|p P'] eqn:EP; [discriminate|]. rewrite <- EP in *.
  exists (fun A => hd (Pt 0 0) (order_by_images P A)). split; [|split].
  - intros A B H. rewrite (H1 A B H). reflexivity.
  - intros g. rewrite H2, H3, EP. reflexivity.
  - rewrite H3, EP. simpl. rewrite peq_canon. reflexivity.
Qed.

(* def-orderable-set is not vacuous: a scalene triangle inscribed in its SEC (gaps 1/3,
   1/6, 1/2 of a turn: one side a diameter), and four points at two distances from C, are
   orderable (C is the SEC's centre and the identity is their only symmetry). *)
Theorem scalene_triangle_orderable : orderable [Pt 1 0; Pt 1 (1 # 3); Pt 1 (1 # 2)].
Proof. apply orderable_of_only_identity; vm_compute; reflexivity. Qed.
Theorem four_points_orderable : orderable [Pt 4 0; Pt 4 (1 # 3); Pt 4 (2 # 3); Pt 1 (1 # 5)].
Proof. apply orderable_of_only_identity; vm_compute; reflexivity. Qed.

(* No leader: a symmetry g of P that moves every point of P leaves no robot that every
   observer designates, since [elect (g P) = elect P] and [elect (g P) = g (elect P)]
   make g fix the robot elected.  P is written canonically, as for [not_orderable]. *)
Theorem not_electable : forall P g, canonical P = true ->
  same_set (map (image g) P) P = true ->
  forallb (fun p => negb (pt_eqb (image g p) p)) P = true -> ~ electable P.
Proof.
  intros P g Hcan Hset Hmoves [elect [Hsame [Hcov Hmem]]].
  pose proof (Hsame _ _ Hset) as E. rewrite Hcov in E.
  apply existsb_exists in Hmem. destruct Hmem as [p [Hp Hpe]].
  rewrite forallb_forall in Hmoves. pose proof (Hmoves p Hp) as Hm.
  assert (Hi : image g p = elect P).
  { unfold image. rewrite <- (canon_peq _ _ (act_peq g _ _ Hpe)). exact E. }
  assert (He : elect P = p).
  { pose proof (canon_image g (elect P)) as C. rewrite E in C.
    rewrite <- (canonical_in P p Hcan Hp), <- (canon_peq _ _ Hpe). symmetry. exact C. }
  rewrite Hi, He, pt_eqb_refl in Hm. discriminate.
Qed.

Definition not_electable_dec (P : list pt) : bool :=
  existsb (fun g => same_set (map (image g) P) P &&
                    forallb (fun p => negb (pt_eqb (image g p) p)) P) (candidates P).

Theorem not_electable_by_candidates : forall P, canonical P = true ->
  not_electable_dec P = true -> ~ electable P.
Proof.
  intros P Hcan H. apply existsb_exists in H. destruct H as [g [_ H]].
  apply andb_true_iff in H. destruct H as [Hset Hmoves].
  exact (not_electable P g Hcan Hset Hmoves).
Qed.

(* ------------------------------------------------------------------ the sine bound *)

(* [chord_apart]'s bound, proved over Coq's real numbers (its axioms are those of the
   standard library's reals; no exported theorem uses this lemma, so their Print
   Assumptions stay closed): for 0 <= g <= 1/4, sin (pi g) >= 3g - 9/2 g^3.  With
   x = pi g in [3g, 4g] within [0, 1]: sin x >= x - x^3/6 (the alternating series,
   [pre_sin_bound]), and x - x^3/6 is increasing on [0, 1]. *)
Module SineBound.
Import Reals Qreals Lra.

Lemma sin_lower_bound : forall g : Q, 0 <= g -> g <= 1 # 4 ->
  (Q2R (sine_bound g) <= sin (PI * Q2R g))%R.
Proof.
  intros g H0 H1. apply Qle_Rle in H0, H1. unfold sine_bound.
  assert (E : Q2R (3 * g - (9 # 2) * (g * g * g)) =
              (3 * Q2R g - 9 / 2 * (Q2R g * Q2R g * Q2R g))%R).
  { rewrite Q2R_minus, !Q2R_mult.
    replace (Q2R 3) with 3%R by (unfold Q2R; simpl; field).
    replace (Q2R (9 # 2)) with (9 / 2)%R by (unfold Q2R; simpl; field). reflexivity. }
  assert (Z : Q2R 0 = 0%R) by (unfold Q2R; simpl; ring).
  assert (F : Q2R (1 # 4) = (1 / 4)%R) by (unfold Q2R; simpl; field).
  rewrite E. rewrite Z in H0. rewrite F in H1. set (y := Q2R g) in *.
  assert (HPI : (3 <= PI <= 4)%R) by (pose proof PI2_3_2; pose proof PI_4; lra).
  assert (Hx : (0 <= PI * y <= 1)%R) by nra.
  destruct (pre_sin_bound (PI * y) 0 (proj1 Hx) ltac:(lra)) as [S _].
  refine (Rle_trans _ _ _ _ S). unfold sin_approx, sin_term. simpl.
  set (x := (PI * y)%R) in *.
  assert (Hxy : (3 * y <= x)%R) by (unfold x; nra).
  assert (D : (x - x * x * x / 6 - (3 * y - 3 * y * (3 * y) * (3 * y) / 6) =
               (x - 3 * y) * (1 - (x * x + x * (3 * y) + 3 * y * (3 * y)) / 6))%R) by field.
  assert (0 <= (x - 3 * y) * (1 - (x * x + x * (3 * y) + 3 * y * (3 * y)) / 6))%R.
  { apply Rmult_le_pos; [lra|]. nra. }
  nra.
Qed.

End SineBound.

(* Gathering.v -- the few definitions the refutations of the gathering statements use
   (Section "Algorithm for Gathering", \label{gathering_algorithm}: GatheringPattern,
   FormGPattern, MakeAsym's epsilon move, lem-vl-move), on top of Exactsym.v.  An exported
   gathering refutation inlines Exactsym.v, then this file.  docs/certificates.md, "Coq:
   the gathering statements".

   Those statements are about runs; their refutations here are facts of one configuration
   (or of a start and one snapshot of a move), which the theorem states for EVERY choice
   the run leaves open that the library does not compute (which robot ElectLeader elects,
   which robot of G_t MakeAsym moves, and in which sense), so that no ordering of the
   paper has to be trusted.

   Robots are unit discs ("fat robots", radius one): two robots overlap iff their centres
   are less than 2 apart.  Points are Exactsym.v's rational polar points about C, the
   centre of the SEC ([sec_centred], (T1)).  The robots' separation ([separated],
   [robots_apart]) and what a reader trusts about it, (T4), are Exactsym.v's ("fat
   robots"); this file trusts nothing beyond Exactsym.v's (T1)-(T4). *)

(* ------------------------------------------------------------------ fat robots *)

(* [separated] ((T4): every two robots more than 2 apart) is Exactsym.v's. *)

(* A4 = exact: "C is not occupied by other robot" iff no centre is at C. *)
Definition occupied_C (P : list pt) : bool := existsb (fun p => Qeq_bool (r2 p) 0) P.
(* A4 = covers: "C is not occupied by other robot" iff no robot's disc (radius one,
   closed) covers C, i.e. no centre within 1 of C.  Not covered implies not occupied. *)
Definition covered_C (P : list pt) : bool := existsb (fun p => Qle_bool (r2 p) 1) P.

(* ------------------------------------------------------------ FormGPattern's move to C *)

(* FormGPattern(R), line 1: "if C is not occupied by other robot: Move R to C".  Whatever
   the path, the move ends with R's centre at C; with R the i-th robot of P, it ends
   overlapping another robot iff some other robot's centre q is less than 2 from C, i.e.
   r2 q < 4 (exact).  This depends on the robots' distances from C only ([map r2 P]). *)
Definition blocked_at_C (rs : list Q) (i : nat) : bool :=
  existsb (fun j => negb (Nat.eqb i j) && Qlt_bool (nth j rs 0) 4) (seq 0 (length rs)).

(* Whichever robot is the leader, its move to C ends overlapping another robot. *)
Definition every_leader_blocked (P : list pt) : bool :=
  forallb (blocked_at_C (map r2 P)) (seq 0 (length P)).

(* ... and so on every configuration with the same distances from C: after any turns about
   C (Make_SymToAsym's and MakeAsym's epsilon moves on a circle about C), for any leader. *)
Theorem every_leader_blocked_spec : forall P, every_leader_blocked P = true ->
  forall P', map r2 P' = map r2 P ->
  forall i, (i < length P')%nat -> blocked_at_C (map r2 P') i = true.
Proof.
  intros P H P' E i Hi. rewrite E. unfold every_leader_blocked in H.
  rewrite forallb_forall in H. apply H. apply in_seq.
  rewrite <- (map_length r2 P), <- E, map_length. lia.
Qed.

(* ------------------------------------------------------------------ a robot part way *)

(* MakeAsym, the branch of an asymmetric pair with |G_t| > 3: "Move v_l, epsilon distance
   away from the current position" (the text names no path).  Read as a turn about C by e
   (either sense), as in its FindAsymmetry branch ("... on the same circle"): the reading
   keeps C and the SEC, which MakeAsym's correctness paragraph needs.  Part way, at the
   rational parameter lam in (0, 1), v_l is at [on_turn v lam e]. *)
Definition on_turn (v : pt) (lam e : Q) : pt := Pt (r2 v) (turn v + lam * e).

(* The snapshot: P with the robot v (compared as a point) replaced by w, written
   canonically. *)
Definition replace_robot (P : list pt) (v w : pt) : list pt :=
  map (fun p => if peq p v then canon w else p) P.

(* Preprocess with its counters advancing (as printed it never ends on an odd polygon:
   Exactsym.v, [preprocess_printed_never_ends]): it replaces G_i by G_ij only when G_i,
   G_j are odd (i <> j) and G_ij is type 4.  When no such G_ij is type 4, calG' = calG. *)
Definition no_merge (P : list pt) : bool :=
  let odd := filter (fun G => Nat.odd (length G)) (polygons P) in
  forallb (fun Gi => forallb (fun Gj =>
    same_set Gi Gj || negb (type4 (merged Gi Gj))) odd) odd.

(* The innermost level G_1 and the outermost G_t of P. *)
Definition r_first (P : list pt) : Q :=
  fold_left (fun m r => if Qle_bool m r then m else r) (radii P) (rmax P).
Definition G_1 (P : list pt) : list pt := level P (r_first P).
Definition G_t (P : list pt) : list pt := level P (rmax P).

(* ElectLeader's first branch: "G_1 is symmetric with degree of symmetry one and the line
   of symmetry passes through either a single vertex or through two vertices": G has at
   least two vertices (a single robot has every line through it as a line of symmetry,
   def-symmetric-conf, so its degree is not one), no half-turn symmetry (no skew line),
   exactly one mirror, and that mirror holds a vertex (Exactsym.v's [through_vertex]).  Then ElectLeader calls
   Make_SymToAsym(G_1) and reports v_l = Elect_Leader_Asym(G_1): a vertex of G_1.  (Its
   first line calls Check_Symmetry_Odd/Even(G_1), whose printed loops never end on such a
   G_1 (Exactsym.v, [printed_loop_never_ends]); read with i++ after every vertex they
   report this symmetry.) *)
Definition elect_leader_first_branch (G : list pt) : bool :=
  Nat.ltb 1 (length G) && negb (skew_symmetric G) &&
  match mirrors G with
  | [s] => through_vertex G s
  | _ => false
  end.

(* lem-vl-move: the start P, MakeAsym's mover v (a vertex of G_t) turned part way, lam of
   its epsilon turn e, and a fresh Look at that snapshot S.  S is written canonically and C
   is still the centre of its SEC (T1) with the same radius; G_t of S is asymmetric, so no
   robot runs MakeAsym again (the lemma's proof: "after v_l starts moving, G_t becomes
   asymmetric"), calG' of S (Preprocess merges nothing) is in O_A, so GatheringPattern
   calls ElectLeader; G_1 of S is G_1 of P and takes ElectLeader's first branch, so the
   leader is a vertex of G_1 (and Make_SymToAsym moves one), and v is in G_t, not G_1:
   ElectLeader selects another robot.  Nothing here depends on which vertex of G_1
   Elect_Leader_Asym's ordering picks, or on a reading of a one-robot G_1. *)
Definition fresh_look_elects_other (P : list pt) (v : pt) (lam e : Q) : bool :=
  let w := on_turn v lam e in
  let S := replace_robot P v w in
  canonical S && distinct S && sec_centred S && Qeq_bool (rmax S) (rmax P) &&
  asymmetric_polygon (G_t S) && no_merge S && calG_in_O_A (polygons S) &&
  same_set (G_1 S) (G_1 P) && elect_leader_first_branch (G_1 S) &&
  negb (mem w (G_1 S)).

(* ================================================= the configuration *)

(* P: (squared distance from C, turn) of each robot. *)
Definition P : list pt := [
  Pt (Qmake 400 1) (Qmake 1 6);
  Pt (Qmake 400 1) (Qmake 1 3);
  Pt (Qmake 400 1) (Qmake 7 12);
  Pt (Qmake 400 1) (Qmake 11 12);
  Pt (Qmake 9 1) (Qmake 1 24);
  Pt (Qmake 9 1) (Qmake 29 120);
  Pt (Qmake 9 1) (Qmake 101 120)].
Definition eps : Q := (Qmake 1 100).
Definition lam : Q := (Qmake 1 2).

(* MakeAsym's branch: no polygon of calG' is asymmetric (FindAsymmetry finds none), <G_1, G_t> is an asymmetric pair (Find_Asymmetry_Pair finds it) and |G_t| > 3, so v_l, a vertex of G_t (which one: any), moves epsilon about C.  Half way, for every such v_l and either sense, a fresh Look's ElectLeader takes its first branch (G_1, an isosceles triangle, has degree of symmetry one and its line passes through a single vertex): it calls Make_SymToAsym(G_1) and elects a vertex of G_1, not v_l. *)
(* P is a set of separated robots written canonically about C, the centre of
   its SEC (T1, T4); the hypotheses of lem-vl-move hold and its conclusion is
   false. *)
Theorem refutes_lem_vl_move :
  canonical P = true /\
  distinct P = true /\
  sec_centred P = true /\
  Nat.leb 5 (length P) = true /\
  separated P = true /\
  no_merge P = true /\
  calG_in_O_A (polygons P) = true /\
  (forallb symmetric_polygon (polygons P) = true) /\
  asymmetric_pair (G_1 P) (G_t P) = true /\
  symmetric_polygon (G_t P) = true /\
  Nat.ltb 3 (length (G_t P)) = true /\
  (forallb (fun v => forallb (fun e => fresh_look_elects_other P v lam e) [eps; - eps]) (G_t P) = true).
Proof.
  split; [vm_compute; reflexivity |].
  split; [vm_compute; reflexivity |].
  split; [vm_compute; reflexivity |].
  split; [vm_compute; reflexivity |].
  split; [vm_compute; reflexivity |].
  split; [vm_compute; reflexivity |].
  split; [vm_compute; reflexivity |].
  split; [vm_compute; reflexivity |].
  split; [vm_compute; reflexivity |].
  split; [vm_compute; reflexivity |].
  split; [vm_compute; reflexivity |].
  vm_compute; reflexivity.
Qed.

Print Assumptions refutes_lem_vl_move.

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
   centre of the SEC ([sec_centred], (T1)).

   What a reader trusts besides Exactsym.v's (T1)-(T3):
   (T4) [separated P] implies that every two robots of P are more than 2 apart (they neither
        overlap nor touch: "Initially all robots are assumed to be stationary and
        separated").  Three sufficient tests, argued before [robots_apart]. *)

(* ------------------------------------------------------------------ fat robots *)

(* Two robots are more than 2 apart: three sufficient tests, none needs a cosine.  Write
   a, b for the distances from C (a^2 = r2 p, b^2 = r2 q) and g in [0, 1/2] for the
   angular gap in turns.
   - [quarter_apart]: g >= 1/4, so cos(2 pi g) <= 0 and |p - q|^2 = a^2 + b^2 -
     2ab cos(2 pi g) >= a^2 + b^2 > 4.
   - [sixth_apart]: g >= 1/6, so cos(2 pi g) <= 1/2 and, for a <= b, |p - q|^2 >=
     a^2 + b^2 - ab = a^2 + b (b - a) >= a^2 = min(a^2, b^2) > 4.
   - [radially_apart]: |p - q| >= |b - a| (triangle inequality through C), and for
     a^2 <= b^2, b - a > 2 iff b > a + 2 iff b^2 > a^2 + 4a + 4 iff
     b^2 - a^2 - 4 > 4a iff (b^2 - a^2 - 4 > 0 and (b^2 - a^2 - 4)^2 > 16 a^2). *)
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
Definition robots_apart (p q : pt) : bool :=
  quarter_apart p q || sixth_apart p q || radially_apart p q.

(* (T4) The robots are separated: every two of them are more than 2 apart. *)
Fixpoint separated (P : list pt) : bool :=
  match P with
  | [] => true
  | p :: rest => forallb (robots_apart p) rest && separated rest
  end.

(* A4 = exact: "C is not occupied by other robot" iff no centre is at C. *)
Definition occupied_C (P : list pt) : bool := existsb (fun p => Qeq_bool (r2 p) 0) P.

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

(* MakeAsym: "Move v_l, epsilon distance away from the current position on the same
   circle": a turn about C by e (either sense).  Part way, at the rational parameter lam in
   (0, 1), v_l is at [on_turn v lam e]. *)
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

(* lem-vl-move: the start P, MakeAsym's mover v (a vertex of G_t) turned part way, lam of
   its epsilon turn e, and a fresh Look at that snapshot S.  S is written canonically and C
   is still the centre of its SEC (T1) with the same radius; G_t of S is asymmetric, so no
   robot runs MakeAsym again (the lemma's proof: "after v_l starts moving, G_t becomes
   asymmetric"), calG' of S (Preprocess merges nothing) is in O_A, so GatheringPattern
   calls ElectLeader, whose leader is "a leader vertex v_l from G_1" (its output); G_1 of
   S is G_1 of P, one robot, which is not v: ElectLeader selects another robot.  (G_1 is
   one robot, symmetric: ElectLeader calls Make_SymToAsym on it, which moves it.) *)
Definition fresh_look_elects_other (P : list pt) (v : pt) (lam e : Q) : bool :=
  let w := on_turn v lam e in
  let S := replace_robot P v w in
  canonical S && distinct S && sec_centred S && Qeq_bool (rmax S) (rmax P) &&
  asymmetric_polygon (G_t S) && no_merge S && calG_in_O_A (polygons S) &&
  same_set (G_1 S) (G_1 P) && Nat.eqb (length (G_1 S)) 1 && symmetric_polygon (G_1 S) &&
  negb (mem w (G_1 S)).

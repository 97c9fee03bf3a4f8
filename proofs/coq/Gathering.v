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

(* Table 1's meshes: for each N, Gappa's proof of the double program's one-step round-off (module
   Gappa_N<N>, gappa -Bcoq) and the lifting lemma with the harness's constants (module Lifting_N<N>). *)
Require Import Gappa.Gappa_library.
Require Import Reals Lra.

Module Gappa_N10.
Section Generated_by_Gappa.
Notation _delta := (float2R (Float2 (3643397502639255) (-52))).
Variable _p_input : R.
Notation _p := ((rounding_float rndNE (53)%positive (-1074)%Z) _p_input).
Notation _ap_ideal := ((_delta * _p)%R).
Notation _ap := ((rounding_float rndNE (53)%positive (-1074)%Z) _ap_ideal).
Notation _beta := (float2R (Float2 (-4159513045721639) (-50))).
Variable _q_input : R.
Notation _q := ((rounding_float rndNE (53)%positive (-1074)%Z) _q_input).
Notation _bq_ideal := ((_beta * _q)%R).
Notation _bq := ((rounding_float rndNE (53)%positive (-1074)%Z) _bq_ideal).
Notation r3 := ((_ap + _bq)%R).
Notation _p1 := ((rounding_float rndNE (53)%positive (-1074)%Z) r3).
Notation r17 := (Float1 (247760988533536771305687694478496380154277693914865356389217)).
Notation r18 := (Float1 (306257084171653319081306918663994503898804694316456471429120)).
Notation _delta_exact := ((r17 / r18)%R).
Notation r15 := ((_delta_exact * _p)%R).
Notation r21 := (Float1 (-53784815726555854523937747366679286727675529322959010423996723531036817249585608705484433)).
Notation r22 := (Float1 (14558511621537888898126202167474500637236590474581529455778362919655804383322842534510592)).
Notation _beta_exact := ((r21 / r22)%R).
Notation r19 := ((_beta_exact * _q)%R).
Notation _p_exact := ((r15 + r19)%R).
Notation r1 := ((_p1 - _p_exact)%R).
Notation _p1_ideal := ((_ap_ideal + _bq_ideal)%R).
Notation r24 := ((_p1 - _p1_ideal)%R).
Notation r26 := ((_p1_ideal - _p_exact)%R).
Notation r23 := ((r24 + r26)%R).
Lemma a1 : r1 = r23.
Proof. first [ring | unfold float2R, Float1, Defs.F2R; simpl; unfold Z.pow_pos; simpl; field]. Qed.
Lemma b1 : r1 = r23.
 apply a1.
Qed.
Notation _gamma := (float2R (Float2 (6739312188114915) (-56))).
Notation _gp_ideal := ((_gamma * _p)%R).
Notation _gp := ((rounding_float rndNE (53)%positive (-1074)%Z) _gp_ideal).
Notation _dq_ideal := ((_delta * _q)%R).
Notation _dq := ((rounding_float rndNE (53)%positive (-1074)%Z) _dq_ideal).
Notation r29 := ((_gp + _dq)%R).
Notation _q1 := ((rounding_float rndNE (53)%positive (-1074)%Z) r29).
Notation r38 := (Float1 (1807641825769423359468802491501)).
Notation r39 := (Float1 (19327539251999843498371389135850)).
Notation _gamma_exact := ((r38 / r39)%R).
Notation r36 := ((_gamma_exact * _p)%R).
Notation r40 := ((_delta_exact * _q)%R).
Notation _q_exact := ((r36 + r40)%R).
Notation r27 := ((_q1 - _q_exact)%R).
Notation _q1_ideal := ((_gp_ideal + _dq_ideal)%R).
Notation r42 := ((_q1 - _q1_ideal)%R).
Notation r44 := ((_q1_ideal - _q_exact)%R).
Notation r41 := ((r42 + r44)%R).
Lemma a2 : r27 = r41.
Proof. first [ring | unfold float2R, Float1, Defs.F2R; simpl; unfold Z.pow_pos; simpl; field]. Qed.
Lemma b2 : r27 = r41.
 apply a2.
Qed.
Notation r48 := (Float1 (-26902437575106681925807266903878992704715617)).
Notation r47 := ((r48 / r18)%R).
Notation r46 := ((r47 * _p)%R).
Notation r51 := (Float1 (-5970821179440564454679434590496408512463223103559587638046324770355239279)).
Notation r50 := ((r51 / r22)%R).
Notation r49 := ((r50 * _q)%R).
Notation r45 := ((r46 + r49)%R).
Lemma a3 : r26 = r45.
Proof. first [ring | unfold float2R, Float1, Defs.F2R; simpl; unfold Z.pow_pos; simpl; field]. Qed.
Lemma b3 : r26 = r45.
 apply a3.
Qed.
Notation r55 := (Float1 (1653192778717867398717027865407)).
Notation r56 := (Float1 (696347988586361041328261577891668148137807052800)).
Notation r54 := ((r55 / r56)%R).
Notation r53 := ((r54 * _p)%R).
Notation r57 := ((r47 * _q)%R).
Notation r52 := ((r53 + r57)%R).
Lemma a4 : r44 = r52.
Proof. first [ring | unfold float2R, Float1, Defs.F2R; simpl; unfold Z.pow_pos; simpl; field]. Qed.
Lemma b4 : r44 = r52.
 apply a4.
Qed.
Definition f1 := Float2 (-89) (-3).
Definition f2 := Float2 (89) (-3).
Definition i1 := makepairF f1 f2.
Notation p1 := (BND _p i1). (* BND(p, [-11.125, 11.125]) *)
Definition f3 := Float2 (-15) (-3).
Definition f4 := Float2 (15) (-3).
Definition i2 := makepairF f3 f4.
Notation p2 := (BND _q i2). (* BND(q, [-1.875, 1.875]) *)
Definition s2 := (p1 /\ p2).
Definition f5 := Float2 (-643630877231412395) (-107).
Definition f6 := Float2 (643630877231412395) (-107).
Definition i3 := makepairF f5 f6.
Notation p3 := (BND r1 i3). (* BND(p1 - p_exact, [-3.96668e-15, 3.96668e-15]) *)
Definition s10 := (not p3).
Definition f7 := Float2 (-412272233861470031) (-109).
Definition f8 := Float2 (412272233861470031) (-109).
Definition i4 := makepairF f7 f8.
Notation p4 := (BND r27 i4). (* BND(q1 - q_exact, [-6.35206e-16, 6.35206e-16]) *)
Definition s11 := (not p4).
Definition s9 := (s10 \/ s11).
Notation r58 := ((Rabs _ap)%R).
Definition f9 := Float2 (0) (0).
Definition f10 := Float2 (9007199254740991) (971).
Definition i5 := makepairF f9 f10.
Notation p5 := (BND r58 i5). (* BND(|ap|, [0, 1.79769e+308]) *)
Definition s12 := (not p5).
Definition s8 := (s9 \/ s12).
Notation r59 := ((Rabs _bq)%R).
Notation p6 := (BND r59 i5). (* BND(|bq|, [0, 1.79769e+308]) *)
Definition s13 := (not p6).
Definition s7 := (s8 \/ s13).
Notation r60 := ((Rabs _p1)%R).
Notation p7 := (BND r60 i5). (* BND(|p1|, [0, 1.79769e+308]) *)
Definition s14 := (not p7).
Definition s6 := (s7 \/ s14).
Notation r61 := ((Rabs _gp)%R).
Notation p8 := (BND r61 i5). (* BND(|gp|, [0, 1.79769e+308]) *)
Definition s15 := (not p8).
Definition s5 := (s6 \/ s15).
Notation r62 := ((Rabs _dq)%R).
Notation p9 := (BND r62 i5). (* BND(|dq|, [0, 1.79769e+308]) *)
Definition s16 := (not p9).
Definition s4 := (s5 \/ s16).
Notation r63 := ((Rabs _q1)%R).
Notation p10 := (BND r63 i5). (* BND(|q1|, [0, 1.79769e+308]) *)
Definition s17 := (not p10).
Definition s3 := (s4 \/ s17).
Definition s1 := (s2 /\ s3).
Definition s18 := (s9 \/ s17).
Definition s20 := (s9 \/ s14).
Definition s19 := (s20 \/ s17).
Definition s22 := (s20 \/ s15).
Definition s21 := (s22 \/ s17).
Definition s26 := (s9 \/ s13).
Definition s25 := (s26 \/ s14).
Definition s24 := (s25 \/ s15).
Definition s23 := (s24 \/ s17).
Definition s28 := (s24 \/ s16).
Definition s27 := (s28 \/ s17).
Lemma l9 : s1 -> s3.
Proof.
 intros h0.
 assert (h1 := h0).
 exact (proj2 h1).
Qed.
Definition f11 := Float2 (2533299826053857) (-48).
Definition i6 := makepairF f9 f11.
Notation p11 := (BND r58 i6). (* BND(|ap|, [0, 9.00009]) *)
Notation p12 := (ABS _ap i6). (* ABS(ap, [0, 9.00009]) *)
Definition f12 := Float2 (-2533299826053857) (-48).
Definition i7 := makepairF f12 f11.
Notation p13 := (BND _ap i7). (* BND(ap, [-9.00009, 9.00009]) *)
Notation p14 := (BND _ap_ideal i7). (* BND(ap_ideal, [-9.00009, 9.00009]) *)
Definition f13 := Float2 (1) (-1).
Definition f14 := Float2 (3643397502639255) (-52).
Definition i8 := makepairF f13 f14.
Notation p15 := (BND _delta i8). (* BND(delta, [0.5, 0.808997]) *)
Lemma t1 : p15.
Proof.
 refine (constant2 _ i8 _) ; finalize.
Qed.
Lemma l14 : s1 -> p15 (* BND(delta, [0.5, 0.808997]) *).
Proof.
 intros h0.
 apply t1.
Qed.
Lemma l16 : s1 -> s2.
Proof.
 intros h0.
 assert (h1 := h0).
 exact (proj1 h1).
Qed.
Lemma l15 : s1 -> p1 (* BND(p, [-11.125, 11.125]) *).
Proof.
 intros h0.
 assert (h1 := l16 h0).
 exact (proj1 h1).
Qed.
Lemma t2 : p15 -> p1 -> p14.
Proof.
 intros h0 h1.
 refine (mul_po _delta _p i8 i1 i7 h0 h1 _) ; finalize.
Qed.
Lemma l13 : s1 -> p14 (* BND(ap_ideal, [-9.00009, 9.00009]) *).
Proof.
 intros h0.
 assert (h1 := l14 h0).
 assert (h2 := l15 h0).
 apply t2. exact h1. exact h2.
Qed.
Lemma t3 : p14 -> p13.
Proof.
 intros h0.
 refine (float_round_ne _ _ _ap_ideal i7 i7 h0 _) ; finalize.
Qed.
Lemma l12 : s1 -> p13 (* BND(ap, [-9.00009, 9.00009]) *).
Proof.
 intros h0.
 assert (h1 := l13 h0).
 apply t3. exact h1.
Qed.
Lemma t4 : p13 -> p12.
Proof.
 intros h0.
 refine (abs_of_bnd_o _ap i7 i6 h0 _) ; finalize.
Qed.
Lemma l11 : s1 -> p12 (* ABS(ap, [0, 9.00009]) *).
Proof.
 intros h0.
 assert (h1 := l12 h0).
 apply t4. exact h1.
Qed.
Lemma t5 : p12 -> p11.
Proof.
 intros h0.
 refine (uabs_of_abs _ap i6 h0) ; finalize.
Qed.
Lemma l10 : s1 -> p11 (* BND(|ap|, [0, 9.00009]) *).
Proof.
 intros h0.
 assert (h1 := l11 h0).
 apply t5. exact h1.
Qed.
Lemma l8 : s1 -> s27.
Proof.
 intros h0.
 assert (h1 := l9 h0).
 assert (h2 := l10 h0).
 refine (simplify (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 2%nat i5))) (Tatom false (Abnd 3%nat i5))) (Tatom false (Abnd 4%nat i5))) (Tatom false (Abnd 5%nat i5))) (Tatom false (Abnd 6%nat i5))) (Tatom false (Abnd 7%nat i5))) (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 3%nat i5))) (Tatom false (Abnd 4%nat i5))) (Tatom false (Abnd 5%nat i5))) (Tatom false (Abnd 6%nat i5))) (Tatom false (Abnd 7%nat i5))) (Abnd 2%nat i6) (List.cons r1 (List.cons r27 (List.cons r58 (List.cons r59 (List.cons r60 (List.cons r61 (List.cons r62 (List.cons r63 List.nil)))))))) h2 h1 _) ; finalize.
Qed.
Definition f15 := Float2 (6831370317448603) (-52).
Definition i9 := makepairF f9 f15.
Notation p16 := (BND r62 i9). (* BND(|dq|, [0, 1.51687]) *)
Notation p17 := (ABS _dq i9). (* ABS(dq, [0, 1.51687]) *)
Definition f16 := Float2 (-6831370317448603) (-52).
Definition i10 := makepairF f16 f15.
Notation p18 := (BND _dq i10). (* BND(dq, [-1.51687, 1.51687]) *)
Definition f17 := Float2 (-27325481269794413) (-54).
Definition f18 := Float2 (27325481269794413) (-54).
Definition i11 := makepairF f17 f18.
Notation p19 := (BND _dq_ideal i11). (* BND(dq_ideal, [-1.51687, 1.51687]) *)
Lemma l21 : s1 -> p2 (* BND(q, [-1.875, 1.875]) *).
Proof.
 intros h0.
 assert (h1 := l16 h0).
 exact (proj2 h1).
Qed.
Lemma t6 : p15 -> p2 -> p19.
Proof.
 intros h0 h1.
 refine (mul_po _delta _q i8 i2 i11 h0 h1 _) ; finalize.
Qed.
Lemma l20 : s1 -> p19 (* BND(dq_ideal, [-1.51687, 1.51687]) *).
Proof.
 intros h0.
 assert (h1 := l14 h0).
 assert (h2 := l21 h0).
 apply t6. exact h1. exact h2.
Qed.
Lemma t7 : p19 -> p18.
Proof.
 intros h0.
 refine (float_round_ne _ _ _dq_ideal i11 i10 h0 _) ; finalize.
Qed.
Lemma l19 : s1 -> p18 (* BND(dq, [-1.51687, 1.51687]) *).
Proof.
 intros h0.
 assert (h1 := l20 h0).
 apply t7. exact h1.
Qed.
Lemma t8 : p18 -> p17.
Proof.
 intros h0.
 refine (abs_of_bnd_o _dq i10 i9 h0 _) ; finalize.
Qed.
Lemma l18 : s1 -> p17 (* ABS(dq, [0, 1.51687]) *).
Proof.
 intros h0.
 assert (h1 := l19 h0).
 apply t8. exact h1.
Qed.
Lemma t9 : p17 -> p16.
Proof.
 intros h0.
 refine (uabs_of_abs _dq i9 h0) ; finalize.
Qed.
Lemma l17 : s1 -> p16 (* BND(|dq|, [0, 1.51687]) *).
Proof.
 intros h0.
 assert (h1 := l18 h0).
 apply t9. exact h1.
Qed.
Lemma l7 : s1 -> s23.
Proof.
 intros h0.
 assert (h1 := l8 h0).
 assert (h2 := l17 h0).
 refine (simplify (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 2%nat i5))) (Tatom false (Abnd 3%nat i5))) (Tatom false (Abnd 4%nat i5))) (Tatom false (Abnd 5%nat i5))) (Tatom false (Abnd 6%nat i5))) (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 2%nat i5))) (Tatom false (Abnd 3%nat i5))) (Tatom false (Abnd 4%nat i5))) (Tatom false (Abnd 6%nat i5))) (Abnd 5%nat i9) (List.cons r1 (List.cons r27 (List.cons r59 (List.cons r60 (List.cons r61 (List.cons r62 (List.cons r63 List.nil))))))) h2 h1 _) ; finalize.
Qed.
Definition f19 := Float2 (7799086960728073) (-50).
Definition i12 := makepairF f9 f19.
Notation p20 := (BND r59 i12). (* BND(|bq|, [0, 6.92698]) *)
Notation p21 := (ABS _bq i12). (* ABS(bq, [0, 6.92698]) *)
Definition f20 := Float2 (-7799086960728073) (-50).
Definition i13 := makepairF f20 f19.
Notation p22 := (BND _bq i13). (* BND(bq, [-6.92698, 6.92698]) *)
Definition f21 := Float2 (-31196347842912293) (-52).
Definition f22 := Float2 (31196347842912293) (-52).
Definition i14 := makepairF f21 f22.
Notation p23 := (BND _bq_ideal i14). (* BND(bq_ideal, [-6.92698, 6.92698]) *)
Definition f23 := Float2 (-4159513045721639) (-50).
Definition f24 := Float2 (-1) (0).
Definition i15 := makepairF f23 f24.
Notation p24 := (BND _beta i15). (* BND(beta, [-3.69439, -1]) *)
Lemma t10 : p24.
Proof.
 refine (constant2 _ i15 _) ; finalize.
Qed.
Lemma l26 : s1 -> p24 (* BND(beta, [-3.69439, -1]) *).
Proof.
 intros h0.
 apply t10.
Qed.
Lemma t11 : p24 -> p2 -> p23.
Proof.
 intros h0 h1.
 refine (mul_no _beta _q i15 i2 i14 h0 h1 _) ; finalize.
Qed.
Lemma l25 : s1 -> p23 (* BND(bq_ideal, [-6.92698, 6.92698]) *).
Proof.
 intros h0.
 assert (h1 := l26 h0).
 assert (h2 := l21 h0).
 apply t11. exact h1. exact h2.
Qed.
Lemma t12 : p23 -> p22.
Proof.
 intros h0.
 refine (float_round_ne _ _ _bq_ideal i14 i13 h0 _) ; finalize.
Qed.
Lemma l24 : s1 -> p22 (* BND(bq, [-6.92698, 6.92698]) *).
Proof.
 intros h0.
 assert (h1 := l25 h0).
 apply t12. exact h1.
Qed.
Lemma t13 : p22 -> p21.
Proof.
 intros h0.
 refine (abs_of_bnd_o _bq i13 i12 h0 _) ; finalize.
Qed.
Lemma l23 : s1 -> p21 (* ABS(bq, [0, 6.92698]) *).
Proof.
 intros h0.
 assert (h1 := l24 h0).
 apply t13. exact h1.
Qed.
Lemma t14 : p21 -> p20.
Proof.
 intros h0.
 refine (uabs_of_abs _bq i12 h0) ; finalize.
Qed.
Lemma l22 : s1 -> p20 (* BND(|bq|, [0, 6.92698]) *).
Proof.
 intros h0.
 assert (h1 := l23 h0).
 apply t14. exact h1.
Qed.
Lemma l6 : s1 -> s21.
Proof.
 intros h0.
 assert (h1 := l7 h0).
 assert (h2 := l22 h0).
 refine (simplify (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 2%nat i5))) (Tatom false (Abnd 3%nat i5))) (Tatom false (Abnd 4%nat i5))) (Tatom false (Abnd 5%nat i5))) (Ttree false (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 3%nat i5))) (Tatom false (Abnd 4%nat i5))) (Tatom false (Abnd 5%nat i5))) (Abnd 2%nat i12) (List.cons r1 (List.cons r27 (List.cons r59 (List.cons r60 (List.cons r61 (List.cons r63 List.nil)))))) h2 h1 _) ; finalize.
Qed.
Definition f25 := Float2 (1171482001449663) (-50).
Definition i16 := makepairF f9 f25.
Notation p25 := (BND r61 i16). (* BND(|gp|, [0, 1.04049]) *)
Notation p26 := (ABS _gp i16). (* ABS(gp, [0, 1.04049]) *)
Definition f26 := Float2 (-1171482001449663) (-50).
Definition i17 := makepairF f26 f25.
Notation p27 := (BND _gp i17). (* BND(gp, [-1.04049, 1.04049]) *)
Notation p28 := (BND _gp_ideal i17). (* BND(gp_ideal, [-1.04049, 1.04049]) *)
Definition f27 := Float2 (1) (-4).
Definition f28 := Float2 (6739312188114915) (-56).
Definition i18 := makepairF f27 f28.
Notation p29 := (BND _gamma i18). (* BND(gamma, [0.0625, 0.0935267]) *)
Lemma t15 : p29.
Proof.
 refine (constant2 _ i18 _) ; finalize.
Qed.
Lemma l31 : s1 -> p29 (* BND(gamma, [0.0625, 0.0935267]) *).
Proof.
 intros h0.
 apply t15.
Qed.
Lemma t16 : p29 -> p1 -> p28.
Proof.
 intros h0 h1.
 refine (mul_po _gamma _p i18 i1 i17 h0 h1 _) ; finalize.
Qed.
Lemma l30 : s1 -> p28 (* BND(gp_ideal, [-1.04049, 1.04049]) *).
Proof.
 intros h0.
 assert (h1 := l31 h0).
 assert (h2 := l15 h0).
 apply t16. exact h1. exact h2.
Qed.
Lemma t17 : p28 -> p27.
Proof.
 intros h0.
 refine (float_round_ne _ _ _gp_ideal i17 i17 h0 _) ; finalize.
Qed.
Lemma l29 : s1 -> p27 (* BND(gp, [-1.04049, 1.04049]) *).
Proof.
 intros h0.
 assert (h1 := l30 h0).
 apply t17. exact h1.
Qed.
Lemma t18 : p27 -> p26.
Proof.
 intros h0.
 refine (abs_of_bnd_o _gp i17 i16 h0 _) ; finalize.
Qed.
Lemma l28 : s1 -> p26 (* ABS(gp, [0, 1.04049]) *).
Proof.
 intros h0.
 assert (h1 := l29 h0).
 apply t18. exact h1.
Qed.
Lemma t19 : p26 -> p25.
Proof.
 intros h0.
 refine (uabs_of_abs _gp i16 h0) ; finalize.
Qed.
Lemma l27 : s1 -> p25 (* BND(|gp|, [0, 1.04049]) *).
Proof.
 intros h0.
 assert (h1 := l28 h0).
 apply t19. exact h1.
Qed.
Lemma l5 : s1 -> s19.
Proof.
 intros h0.
 assert (h1 := l6 h0).
 assert (h2 := l27 h0).
 refine (simplify (Ttree false (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 2%nat i5))) (Tatom false (Abnd 3%nat i5))) (Tatom false (Abnd 4%nat i5))) (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 2%nat i5))) (Tatom false (Abnd 4%nat i5))) (Abnd 3%nat i16) (List.cons r1 (List.cons r27 (List.cons r60 (List.cons r61 (List.cons r63 List.nil))))) h2 h1 _) ; finalize.
Qed.
Definition f29 := Float2 (4483071566235875) (-48).
Definition i19 := makepairF f9 f29.
Notation p30 := (BND r60 i19). (* BND(|p1|, [0, 15.9271]) *)
Notation p31 := (ABS _p1 i19). (* ABS(p1, [0, 15.9271]) *)
Definition f30 := Float2 (-4483071566235875) (-48).
Definition i20 := makepairF f30 f29.
Notation p32 := (BND _p1 i20). (* BND(p1, [-15.9271, 15.9271]) *)
Definition f31 := Float2 (-17932286264943501) (-50).
Definition f32 := Float2 (17932286264943501) (-50).
Definition i21 := makepairF f31 f32.
Notation p33 := (BND r3 i21). (* BND(ap + bq, [-15.9271, 15.9271]) *)
Lemma t20 : p13 -> p22 -> p33.
Proof.
 intros h0 h1.
 refine (add _ap _bq i7 i13 i21 h0 h1 _) ; finalize.
Qed.
Lemma l35 : s1 -> p33 (* BND(ap + bq, [-15.9271, 15.9271]) *).
Proof.
 intros h0.
 assert (h1 := l12 h0).
 assert (h2 := l24 h0).
 apply t20. exact h1. exact h2.
Qed.
Lemma t21 : p33 -> p32.
Proof.
 intros h0.
 refine (float_round_ne _ _ r3 i21 i20 h0 _) ; finalize.
Qed.
Lemma l34 : s1 -> p32 (* BND(p1, [-15.9271, 15.9271]) *).
Proof.
 intros h0.
 assert (h1 := l35 h0).
 apply t21. exact h1.
Qed.
Lemma t22 : p32 -> p31.
Proof.
 intros h0.
 refine (abs_of_bnd_o _p1 i20 i19 h0 _) ; finalize.
Qed.
Lemma l33 : s1 -> p31 (* ABS(p1, [0, 15.9271]) *).
Proof.
 intros h0.
 assert (h1 := l34 h0).
 apply t22. exact h1.
Qed.
Lemma t23 : p31 -> p30.
Proof.
 intros h0.
 refine (uabs_of_abs _p1 i19 h0) ; finalize.
Qed.
Lemma l32 : s1 -> p30 (* BND(|p1|, [0, 15.9271]) *).
Proof.
 intros h0.
 assert (h1 := l33 h0).
 apply t23. exact h1.
Qed.
Lemma l4 : s1 -> s18.
Proof.
 intros h0.
 assert (h1 := l5 h0).
 assert (h2 := l32 h0).
 refine (simplify (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 2%nat i5))) (Tatom false (Abnd 3%nat i5))) (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 3%nat i5))) (Abnd 2%nat i19) (List.cons r1 (List.cons r27 (List.cons r60 (List.cons r63 List.nil)))) h2 h1 _) ; finalize.
Qed.
Definition f33 := Float2 (1439662290405907) (-49).
Definition i22 := makepairF f9 f33.
Notation p34 := (BND r63 i22). (* BND(|q1|, [0, 2.55735]) *)
Notation p35 := (ABS _q1 i22). (* ABS(q1, [0, 2.55735]) *)
Definition f34 := Float2 (-1439662290405907) (-49).
Definition i23 := makepairF f34 f33.
Notation p36 := (BND _q1 i23). (* BND(q1, [-2.55735, 2.55735]) *)
Notation p37 := (BND r29 i23). (* BND(gp + dq, [-2.55735, 2.55735]) *)
Definition f35 := Float2 (-1707842579362151) (-50).
Definition f36 := Float2 (1707842579362151) (-50).
Definition i24 := makepairF f35 f36.
Notation p38 := (BND _dq i24). (* BND(dq, [-1.51687, 1.51687]) *)
Lemma t24 : p27 -> p38 -> p37.
Proof.
 intros h0 h1.
 refine (add _gp _dq i17 i24 i23 h0 h1 _) ; finalize.
Qed.
Lemma l39 : s1 -> p37 (* BND(gp + dq, [-2.55735, 2.55735]) *).
Proof.
 intros h0.
 assert (h1 := l29 h0).
 assert (h2 := l19 h0).
 apply t24. exact h1. refine (subset _dq i10 i24 h2 _) ; finalize.
Qed.
Lemma t25 : p37 -> p36.
Proof.
 intros h0.
 refine (float_round_ne _ _ r29 i23 i23 h0 _) ; finalize.
Qed.
Lemma l38 : s1 -> p36 (* BND(q1, [-2.55735, 2.55735]) *).
Proof.
 intros h0.
 assert (h1 := l39 h0).
 apply t25. exact h1.
Qed.
Lemma t26 : p36 -> p35.
Proof.
 intros h0.
 refine (abs_of_bnd_o _q1 i23 i22 h0 _) ; finalize.
Qed.
Lemma l37 : s1 -> p35 (* ABS(q1, [0, 2.55735]) *).
Proof.
 intros h0.
 assert (h1 := l38 h0).
 apply t26. exact h1.
Qed.
Lemma t27 : p35 -> p34.
Proof.
 intros h0.
 refine (uabs_of_abs _q1 i22 h0) ; finalize.
Qed.
Lemma l36 : s1 -> p34 (* BND(|q1|, [0, 2.55735]) *).
Proof.
 intros h0.
 assert (h1 := l37 h0).
 apply t27. exact h1.
Qed.
Lemma l3 : s1 -> s9.
Proof.
 intros h0.
 assert (h1 := l4 h0).
 assert (h2 := l36 h0).
 refine (simplify (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 2%nat i5))) (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Abnd 2%nat i22) (List.cons r1 (List.cons r27 (List.cons r63 List.nil))) h2 h1 _) ; finalize.
Qed.
Notation p39 := (BND r23 i3). (* BND(p1 - p1_ideal + (p1_ideal - p_exact), [-3.96668e-15, 3.96668e-15]) *)
Definition f37 := Float2 (-5) (-51).
Definition f38 := Float2 (5) (-51).
Definition i25 := makepairF f37 f38.
Notation p40 := (BND r24 i25). (* BND(p1 - p1_ideal, [-2.22045e-15, 2.22045e-15]) *)
Notation r65 := ((_p1 - r3)%R).
Notation r66 := ((r3 - _p1_ideal)%R).
Notation r64 := ((r65 + r66)%R).
Notation p41 := (BND r64 i25). (* BND(p1 - (ap + bq) + (ap + bq - p1_ideal), [-2.22045e-15, 2.22045e-15]) *)
Definition f39 := Float2 (-1) (-50).
Definition f40 := Float2 (1) (-50).
Definition i26 := makepairF f39 f40.
Notation p42 := (BND r65 i26). (* BND(p1 - (ap + bq), [-8.88178e-16, 8.88178e-16]) *)
Definition f41 := Float2 (1) (4).
Definition i27 := makepairF f9 f41.
Notation p43 := (ABS r3 i27). (* ABS(ap + bq, [0, 16]) *)
Definition f42 := Float2 (-1) (4).
Definition i28 := makepairF f42 f41.
Notation p44 := (BND r3 i28). (* BND(ap + bq, [-16, 16]) *)
Lemma t28 : p44 -> p43.
Proof.
 intros h0.
 refine (abs_of_bnd_o r3 i28 i27 h0 _) ; finalize.
Qed.
Lemma l45 : s1 -> p43 (* ABS(ap + bq, [0, 16]) *).
Proof.
 intros h0.
 assert (h1 := l35 h0).
 apply t28. refine (subset r3 i21 i28 h1 _) ; finalize.
Qed.
Lemma t29 : p43 -> p42.
Proof.
 intros h0.
 refine (float_absolute_wide_ne _ _ r3 i27 i26 h0 _) ; finalize.
Qed.
Lemma l44 : s1 -> p42 (* BND(p1 - (ap + bq), [-8.88178e-16, 8.88178e-16]) *).
Proof.
 intros h0.
 assert (h1 := l45 h0).
 apply t29. exact h1.
Qed.
Definition f43 := Float2 (-3) (-51).
Definition f44 := Float2 (3) (-51).
Definition i29 := makepairF f43 f44.
Notation p45 := (BND r66 i29). (* BND(ap + bq - p1_ideal, [-1.33227e-15, 1.33227e-15]) *)
Notation r68 := ((_ap - _ap_ideal)%R).
Notation r69 := ((_bq - _bq_ideal)%R).
Notation r67 := ((r68 + r69)%R).
Notation p46 := (BND r67 i29). (* BND(ap - ap_ideal + (bq - bq_ideal), [-1.33227e-15, 1.33227e-15]) *)
Notation p47 := (BND r68 i26). (* BND(ap - ap_ideal, [-8.88178e-16, 8.88178e-16]) *)
Notation p48 := (ABS _ap_ideal i27). (* ABS(ap_ideal, [0, 16]) *)
Definition f45 := Float2 (1) (0).
Definition i30 := makepairF f13 f45.
Notation p49 := (ABS _delta i30). (* ABS(delta, [0.5, 1]) *)
Notation p50 := (BND _delta i30). (* BND(delta, [0.5, 1]) *)
Lemma t30 : p50 -> p49.
Proof.
 intros h0.
 refine (abs_of_bnd_p _delta i30 i30 h0 _) ; finalize.
Qed.
Lemma l50 : s1 -> p49 (* ABS(delta, [0.5, 1]) *).
Proof.
 intros h0.
 assert (h1 := l14 h0).
 apply t30. refine (subset _delta i8 i30 h1 _) ; finalize.
Qed.
Notation p51 := (ABS _p i27). (* ABS(p, [0, 16]) *)
Notation p52 := (BND _p i28). (* BND(p, [-16, 16]) *)
Lemma t31 : p52 -> p51.
Proof.
 intros h0.
 refine (abs_of_bnd_o _p i28 i27 h0 _) ; finalize.
Qed.
Lemma l51 : s1 -> p51 (* ABS(p, [0, 16]) *).
Proof.
 intros h0.
 assert (h1 := l15 h0).
 apply t31. refine (subset _p i1 i28 h1 _) ; finalize.
Qed.
Lemma t32 : p49 -> p51 -> p48.
Proof.
 intros h0 h1.
 refine (mul_aa _delta _p i30 i27 i27 h0 h1 _) ; finalize.
Qed.
Lemma l49 : s1 -> p48 (* ABS(ap_ideal, [0, 16]) *).
Proof.
 intros h0.
 assert (h1 := l50 h0).
 assert (h2 := l51 h0).
 apply t32. exact h1. exact h2.
Qed.
Lemma t33 : p48 -> p47.
Proof.
 intros h0.
 refine (float_absolute_wide_ne _ _ _ap_ideal i27 i26 h0 _) ; finalize.
Qed.
Lemma l48 : s1 -> p47 (* BND(ap - ap_ideal, [-8.88178e-16, 8.88178e-16]) *).
Proof.
 intros h0.
 assert (h1 := l49 h0).
 apply t33. exact h1.
Qed.
Definition f46 := Float2 (-1) (-51).
Definition f47 := Float2 (1) (-51).
Definition i31 := makepairF f46 f47.
Notation p53 := (BND r69 i31). (* BND(bq - bq_ideal, [-4.44089e-16, 4.44089e-16]) *)
Definition f48 := Float2 (1) (3).
Definition i32 := makepairF f9 f48.
Notation p54 := (ABS _bq_ideal i32). (* ABS(bq_ideal, [0, 8]) *)
Definition f49 := Float2 (1) (2).
Definition i33 := makepairF f45 f49.
Notation p55 := (ABS _beta i33). (* ABS(beta, [1, 4]) *)
Definition f50 := Float2 (-1) (2).
Definition i34 := makepairF f50 f24.
Notation p56 := (BND _beta i34). (* BND(beta, [-4, -1]) *)
Lemma t34 : p56 -> p55.
Proof.
 intros h0.
 refine (abs_of_bnd_n _beta i34 i33 h0 _) ; finalize.
Qed.
Lemma l54 : s1 -> p55 (* ABS(beta, [1, 4]) *).
Proof.
 intros h0.
 assert (h1 := l26 h0).
 apply t34. refine (subset _beta i15 i34 h1 _) ; finalize.
Qed.
Definition f51 := Float2 (1) (1).
Definition i35 := makepairF f9 f51.
Notation p57 := (ABS _q i35). (* ABS(q, [0, 2]) *)
Definition f52 := Float2 (-1) (1).
Definition i36 := makepairF f52 f51.
Notation p58 := (BND _q i36). (* BND(q, [-2, 2]) *)
Lemma t35 : p58 -> p57.
Proof.
 intros h0.
 refine (abs_of_bnd_o _q i36 i35 h0 _) ; finalize.
Qed.
Lemma l55 : s1 -> p57 (* ABS(q, [0, 2]) *).
Proof.
 intros h0.
 assert (h1 := l21 h0).
 apply t35. refine (subset _q i2 i36 h1 _) ; finalize.
Qed.
Lemma t36 : p55 -> p57 -> p54.
Proof.
 intros h0 h1.
 refine (mul_aa _beta _q i33 i35 i32 h0 h1 _) ; finalize.
Qed.
Lemma l53 : s1 -> p54 (* ABS(bq_ideal, [0, 8]) *).
Proof.
 intros h0.
 assert (h1 := l54 h0).
 assert (h2 := l55 h0).
 apply t36. exact h1. exact h2.
Qed.
Lemma t37 : p54 -> p53.
Proof.
 intros h0.
 refine (float_absolute_wide_ne _ _ _bq_ideal i32 i31 h0 _) ; finalize.
Qed.
Lemma l52 : s1 -> p53 (* BND(bq - bq_ideal, [-4.44089e-16, 4.44089e-16]) *).
Proof.
 intros h0.
 assert (h1 := l53 h0).
 apply t37. exact h1.
Qed.
Lemma t38 : p47 -> p53 -> p46.
Proof.
 intros h0 h1.
 refine (add r68 r69 i26 i31 i29 h0 h1 _) ; finalize.
Qed.
Lemma l47 : s1 -> p46 (* BND(ap - ap_ideal + (bq - bq_ideal), [-1.33227e-15, 1.33227e-15]) *).
Proof.
 intros h0.
 assert (h1 := l48 h0).
 assert (h2 := l52 h0).
 apply t38. exact h1. exact h2.
Qed.
Lemma t39 : p46 -> p45.
Proof.
 intros h0.
 refine (add_mibs _ _ _ _ i29 h0) ; finalize.
Qed.
Lemma l46 : s1 -> p45 (* BND(ap + bq - p1_ideal, [-1.33227e-15, 1.33227e-15]) *).
Proof.
 intros h0.
 assert (h1 := l47 h0).
 apply t39. exact h1.
Qed.
Lemma t40 : p42 -> p45 -> p41.
Proof.
 intros h0 h1.
 refine (add r65 r66 i26 i29 i25 h0 h1 _) ; finalize.
Qed.
Lemma l43 : s1 -> p41 (* BND(p1 - (ap + bq) + (ap + bq - p1_ideal), [-2.22045e-15, 2.22045e-15]) *).
Proof.
 intros h0.
 assert (h1 := l44 h0).
 assert (h2 := l46 h0).
 apply t40. exact h1. exact h2.
Qed.
Lemma t41 : p41 -> p40.
Proof.
 intros h0.
 refine (sub_xals _ _ _ i25 h0) ; finalize.
Qed.
Lemma l42 : s1 -> p40 (* BND(p1 - p1_ideal, [-2.22045e-15, 2.22045e-15]) *).
Proof.
 intros h0.
 assert (h1 := l43 h0).
 apply t41. exact h1.
Qed.
Definition f53 := Float2 (-283342907041772715) (-107).
Definition f54 := Float2 (283342907041772715) (-107).
Definition i37 := makepairF f53 f54.
Notation p59 := (BND r26 i37). (* BND(p1_ideal - p_exact, [-1.74624e-15, 1.74624e-15]) *)
Notation p60 := (BND r45 i37). (* BND(-26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120 * p + -5970821179440564454679434590496408512463223103559587638046324770355239279 / 14558511621537888898126202167474500637236590474581529455778362919655804383322842534510592 * q, [-1.74624e-15, 1.74624e-15]) *)
Definition f55 := Float2 (-634271264147409225) (-109).
Definition f56 := Float2 (634271264147409225) (-109).
Definition i38 := makepairF f55 f56.
Notation p61 := (BND r46 i38). (* BND(-26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120 * p, [-9.7725e-16, 9.7725e-16]) *)
Definition f57 := Float2 (-14253286834773241) (-107).
Definition f58 := Float2 (-1) (-54).
Definition i39 := makepairF f57 f58.
Notation p62 := (BND r47 i39). (* BND(-26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120, [-8.78427e-17, -5.55112e-17]) *)
Definition f59 := Float2 (-347705856133536463) (86).
Definition f60 := Float2 (-1) (144).
Definition i40 := makepairF f59 f60.
Notation p63 := (BND r48 i40). (* BND(-26902437575106681925807266903878992704715617, [-2.69024e+43, -2.23007e+43]) *)
Lemma t42 : p63.
Proof.
 refine (constant1 _ i40 _) ; finalize.
Qed.
Lemma l60 : s1 -> p63 (* BND(-26902437575106681925807266903878992704715617, [-2.69024e+43, -2.23007e+43]) *).
Proof.
 intros h0.
 apply t42.
Qed.
Definition f61 := Float2 (219728681850027027) (140).
Definition f62 := Float2 (1) (198).
Definition i41 := makepairF f61 f62.
Notation p64 := (BND r18 i41). (* BND(306257084171653319081306918663994503898804694316456471429120, [3.06257e+59, 4.01735e+59]) *)
Lemma t43 : p64.
Proof.
 refine (constant1 _ i41 _) ; finalize.
Qed.
Lemma l61 : s1 -> p64 (* BND(306257084171653319081306918663994503898804694316456471429120, [3.06257e+59, 4.01735e+59]) *).
Proof.
 intros h0.
 apply t43.
Qed.
Lemma t44 : p63 -> p64 -> p62.
Proof.
 intros h0 h1.
 refine (div_np r48 r18 i40 i41 i39 h0 h1 _) ; finalize.
Qed.
Lemma l59 : s1 -> p62 (* BND(-26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120, [-8.78427e-17, -5.55112e-17]) *).
Proof.
 intros h0.
 assert (h1 := l60 h0).
 assert (h2 := l61 h0).
 apply t44. exact h1. exact h2.
Qed.
Lemma t45 : p62 -> p1 -> p61.
Proof.
 intros h0 h1.
 refine (mul_no r47 _p i39 i1 i38 h0 h1 _) ; finalize.
Qed.
Lemma l58 : s1 -> p61 (* BND(-26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120 * p, [-9.7725e-16, 9.7725e-16]) *).
Proof.
 intros h0.
 assert (h1 := l59 h0).
 assert (h2 := l15 h0).
 apply t45. exact h1. exact h2.
Qed.
Definition f63 := Float2 (-499100364019681635) (-109).
Definition f64 := Float2 (499100364019681635) (-109).
Definition i42 := makepairF f63 f64.
Notation p65 := (BND r49 i42). (* BND(-5970821179440564454679434590496408512463223103559587638046324770355239279 / 14558511621537888898126202167474500637236590474581529455778362919655804383322842534510592 * q, [-7.68986e-16, 7.68986e-16]) *)
Definition f65 := Float2 (-33273357601312109) (-106).
Definition f66 := Float2 (-1) (-52).
Definition i43 := makepairF f65 f66.
Notation p66 := (BND r50 i43). (* BND(-5970821179440564454679434590496408512463223103559587638046324770355239279 / 14558511621537888898126202167474500637236590474581529455778362919655804383322842534510592, [-4.10126e-16, -2.22045e-16]) *)
Definition f67 := Float2 (-243508913248898345) (184).
Definition f68 := Float2 (-1) (241).
Definition i44 := makepairF f67 f68.
Notation p67 := (BND r51 i44). (* BND(-5970821179440564454679434590496408512463223103559587638046324770355239279, [-5.97082e+72, -3.53369e+72]) *)
Lemma t46 : p67.
Proof.
 refine (constant1 _ i44 _) ; finalize.
Qed.
Lemma l64 : s1 -> p67 (* BND(-5970821179440564454679434590496408512463223103559587638046324770355239279, [-5.97082e+72, -3.53369e+72]) *).
Proof.
 intros h0.
 apply t46.
Qed.
Definition f69 := Float2 (527348836440064865) (234).
Definition f70 := Float2 (1) (293).
Definition i45 := makepairF f69 f70.
Notation p68 := (BND r22 i45). (* BND(14558511621537888898126202167474500637236590474581529455778362919655804383322842534510592, [1.45585e+88, 1.59143e+88]) *)
Lemma t47 : p68.
Proof.
 refine (constant1 _ i45 _) ; finalize.
Qed.
Lemma l65 : s1 -> p68 (* BND(14558511621537888898126202167474500637236590474581529455778362919655804383322842534510592, [1.45585e+88, 1.59143e+88]) *).
Proof.
 intros h0.
 apply t47.
Qed.
Lemma t48 : p67 -> p68 -> p66.
Proof.
 intros h0 h1.
 refine (div_np r51 r22 i44 i45 i43 h0 h1 _) ; finalize.
Qed.
Lemma l63 : s1 -> p66 (* BND(-5970821179440564454679434590496408512463223103559587638046324770355239279 / 14558511621537888898126202167474500637236590474581529455778362919655804383322842534510592, [-4.10126e-16, -2.22045e-16]) *).
Proof.
 intros h0.
 assert (h1 := l64 h0).
 assert (h2 := l65 h0).
 apply t48. exact h1. exact h2.
Qed.
Lemma t49 : p66 -> p2 -> p65.
Proof.
 intros h0 h1.
 refine (mul_no r50 _q i43 i2 i42 h0 h1 _) ; finalize.
Qed.
Lemma l62 : s1 -> p65 (* BND(-5970821179440564454679434590496408512463223103559587638046324770355239279 / 14558511621537888898126202167474500637236590474581529455778362919655804383322842534510592 * q, [-7.68986e-16, 7.68986e-16]) *).
Proof.
 intros h0.
 assert (h1 := l63 h0).
 assert (h2 := l21 h0).
 apply t49. exact h1. exact h2.
Qed.
Lemma t50 : p61 -> p65 -> p60.
Proof.
 intros h0 h1.
 refine (add r46 r49 i38 i42 i37 h0 h1 _) ; finalize.
Qed.
Lemma l57 : s1 -> p60 (* BND(-26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120 * p + -5970821179440564454679434590496408512463223103559587638046324770355239279 / 14558511621537888898126202167474500637236590474581529455778362919655804383322842534510592 * q, [-1.74624e-15, 1.74624e-15]) *).
Proof.
 intros h0.
 assert (h1 := l58 h0).
 assert (h2 := l62 h0).
 apply t50. exact h1. exact h2.
Qed.
Definition i46 := makepairF f9 f9.
Notation p69 := (REL r26 r45 i46). (* REL(p1_ideal - p_exact, -26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120 * p + -5970821179440564454679434590496408512463223103559587638046324770355239279 / 14558511621537888898126202167474500637236590474581529455778362919655804383322842534510592 * q, [0, 0]) *)
Notation p70 := (r26 = r45). (* EQL(p1_ideal - p_exact, -26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120 * p + -5970821179440564454679434590496408512463223103559587638046324770355239279 / 14558511621537888898126202167474500637236590474581529455778362919655804383322842534510592 * q) *)
Lemma t51 : p70.
Proof.
 refine (b3) ; finalize.
Qed.
Lemma l67 : s1 -> p70 (* EQL(p1_ideal - p_exact, -26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120 * p + -5970821179440564454679434590496408512463223103559587638046324770355239279 / 14558511621537888898126202167474500637236590474581529455778362919655804383322842534510592 * q) *).
Proof.
 intros h0.
 apply t51.
Qed.
Notation p71 := (REL r45 r45 i46). (* REL(-26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120 * p + -5970821179440564454679434590496408512463223103559587638046324770355239279 / 14558511621537888898126202167474500637236590474581529455778362919655804383322842534510592 * q, -26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120 * p + -5970821179440564454679434590496408512463223103559587638046324770355239279 / 14558511621537888898126202167474500637236590474581529455778362919655804383322842534510592 * q, [0, 0]) *)
Lemma t52 : p71.
Proof.
 refine (rel_refl r45 i46 _) ; finalize.
Qed.
Lemma l68 : s1 -> p71 (* REL(-26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120 * p + -5970821179440564454679434590496408512463223103559587638046324770355239279 / 14558511621537888898126202167474500637236590474581529455778362919655804383322842534510592 * q, -26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120 * p + -5970821179440564454679434590496408512463223103559587638046324770355239279 / 14558511621537888898126202167474500637236590474581529455778362919655804383322842534510592 * q, [0, 0]) *).
Proof.
 intros h0.
 apply t52.
Qed.
Lemma t53 : p70 -> p71 -> p69.
Proof.
 intros h0 h1.
 refine (rel_rewrite_1 r26 r45 r45 i46 h0 h1) ; finalize.
Qed.
Lemma l66 : s1 -> p69 (* REL(p1_ideal - p_exact, -26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120 * p + -5970821179440564454679434590496408512463223103559587638046324770355239279 / 14558511621537888898126202167474500637236590474581529455778362919655804383322842534510592 * q, [0, 0]) *).
Proof.
 intros h0.
 assert (h1 := l67 h0).
 assert (h2 := l68 h0).
 apply t53. exact h1. exact h2.
Qed.
Lemma t54 : p60 -> p69 -> p59.
Proof.
 intros h0 h1.
 refine (bnd_of_bnd_rel_o r26 r45 i37 i46 i37 h0 h1 _) ; finalize.
Qed.
Lemma l56 : s1 -> p59 (* BND(p1_ideal - p_exact, [-1.74624e-15, 1.74624e-15]) *).
Proof.
 intros h0.
 assert (h1 := l57 h0).
 assert (h2 := l66 h0).
 apply t54. exact h1. exact h2.
Qed.
Lemma t55 : p40 -> p59 -> p39.
Proof.
 intros h0 h1.
 refine (add r24 r26 i25 i37 i3 h0 h1 _) ; finalize.
Qed.
Lemma l41 : s1 -> p39 (* BND(p1 - p1_ideal + (p1_ideal - p_exact), [-3.96668e-15, 3.96668e-15]) *).
Proof.
 intros h0.
 assert (h1 := l42 h0).
 assert (h2 := l56 h0).
 apply t55. exact h1. exact h2.
Qed.
Notation p72 := (REL r1 r23 i46). (* REL(p1 - p_exact, p1 - p1_ideal + (p1_ideal - p_exact), [0, 0]) *)
Notation p73 := (r1 = r23). (* EQL(p1 - p_exact, p1 - p1_ideal + (p1_ideal - p_exact)) *)
Lemma t56 : p73.
Proof.
 refine (b1) ; finalize.
Qed.
Lemma l70 : s1 -> p73 (* EQL(p1 - p_exact, p1 - p1_ideal + (p1_ideal - p_exact)) *).
Proof.
 intros h0.
 apply t56.
Qed.
Notation p74 := (REL r23 r23 i46). (* REL(p1 - p1_ideal + (p1_ideal - p_exact), p1 - p1_ideal + (p1_ideal - p_exact), [0, 0]) *)
Lemma t57 : p74.
Proof.
 refine (rel_refl r23 i46 _) ; finalize.
Qed.
Lemma l71 : s1 -> p74 (* REL(p1 - p1_ideal + (p1_ideal - p_exact), p1 - p1_ideal + (p1_ideal - p_exact), [0, 0]) *).
Proof.
 intros h0.
 apply t57.
Qed.
Lemma t58 : p73 -> p74 -> p72.
Proof.
 intros h0 h1.
 refine (rel_rewrite_1 r1 r23 r23 i46 h0 h1) ; finalize.
Qed.
Lemma l69 : s1 -> p72 (* REL(p1 - p_exact, p1 - p1_ideal + (p1_ideal - p_exact), [0, 0]) *).
Proof.
 intros h0.
 assert (h1 := l70 h0).
 assert (h2 := l71 h0).
 apply t58. exact h1. exact h2.
Qed.
Lemma t59 : p39 -> p72 -> p3.
Proof.
 intros h0 h1.
 refine (bnd_of_bnd_rel_o r1 r23 i3 i46 i3 h0 h1 _) ; finalize.
Qed.
Lemma l40 : s1 -> p3 (* BND(p1 - p_exact, [-3.96668e-15, 3.96668e-15]) *).
Proof.
 intros h0.
 assert (h1 := l41 h0).
 assert (h2 := l69 h0).
 apply t59. exact h1. exact h2.
Qed.
Lemma l2 : s1 -> s11.
Proof.
 intros h0.
 assert (h1 := l3 h0).
 assert (h2 := l40 h0).
 refine (simplify (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 1%nat i4)) (Abnd 0%nat i3) (List.cons r1 (List.cons r27 List.nil)) h2 h1 _) ; finalize.
Qed.
Notation p75 := (BND r41 i4). (* BND(q1 - q1_ideal + (q1_ideal - q_exact), [-6.35206e-16, 6.35206e-16]) *)
Notation p76 := (BND r42 i31). (* BND(q1 - q1_ideal, [-4.44089e-16, 4.44089e-16]) *)
Notation r71 := ((_q1 - r29)%R).
Notation r72 := ((r29 - _q1_ideal)%R).
Notation r70 := ((r71 + r72)%R).
Notation p77 := (BND r70 i31). (* BND(q1 - (gp + dq) + (gp + dq - q1_ideal), [-4.44089e-16, 4.44089e-16]) *)
Definition f71 := Float2 (1) (-52).
Definition i47 := makepairF f66 f71.
Notation p78 := (BND r71 i47). (* BND(q1 - (gp + dq), [-2.22045e-16, 2.22045e-16]) *)
Definition i48 := makepairF f9 f49.
Notation p79 := (ABS r29 i48). (* ABS(gp + dq, [0, 4]) *)
Definition i49 := makepairF f50 f49.
Notation p80 := (BND r29 i49). (* BND(gp + dq, [-4, 4]) *)
Lemma t60 : p80 -> p79.
Proof.
 intros h0.
 refine (abs_of_bnd_o r29 i49 i48 h0 _) ; finalize.
Qed.
Lemma l77 : s1 -> p79 (* ABS(gp + dq, [0, 4]) *).
Proof.
 intros h0.
 assert (h1 := l39 h0).
 apply t60. refine (subset r29 i23 i49 h1 _) ; finalize.
Qed.
Lemma t61 : p79 -> p78.
Proof.
 intros h0.
 refine (float_absolute_wide_ne _ _ r29 i48 i47 h0 _) ; finalize.
Qed.
Lemma l76 : s1 -> p78 (* BND(q1 - (gp + dq), [-2.22045e-16, 2.22045e-16]) *).
Proof.
 intros h0.
 assert (h1 := l77 h0).
 apply t61. exact h1.
Qed.
Notation p81 := (BND r72 i47). (* BND(gp + dq - q1_ideal, [-2.22045e-16, 2.22045e-16]) *)
Notation r74 := ((_gp - _gp_ideal)%R).
Notation r75 := ((_dq - _dq_ideal)%R).
Notation r73 := ((r74 + r75)%R).
Notation p82 := (BND r73 i47). (* BND(gp - gp_ideal + (dq - dq_ideal), [-2.22045e-16, 2.22045e-16]) *)
Definition f72 := Float2 (-1) (-53).
Definition f73 := Float2 (1) (-53).
Definition i50 := makepairF f72 f73.
Notation p83 := (BND r74 i50). (* BND(gp - gp_ideal, [-1.11022e-16, 1.11022e-16]) *)
Notation p84 := (ABS _gp_ideal i35). (* ABS(gp_ideal, [0, 2]) *)
Definition f74 := Float2 (1) (-3).
Definition i51 := makepairF f27 f74.
Notation p85 := (ABS _gamma i51). (* ABS(gamma, [0.0625, 0.125]) *)
Notation p86 := (BND _gamma i51). (* BND(gamma, [0.0625, 0.125]) *)
Lemma t62 : p86 -> p85.
Proof.
 intros h0.
 refine (abs_of_bnd_p _gamma i51 i51 h0 _) ; finalize.
Qed.
Lemma l82 : s1 -> p85 (* ABS(gamma, [0.0625, 0.125]) *).
Proof.
 intros h0.
 assert (h1 := l31 h0).
 apply t62. refine (subset _gamma i18 i51 h1 _) ; finalize.
Qed.
Lemma t63 : p85 -> p51 -> p84.
Proof.
 intros h0 h1.
 refine (mul_aa _gamma _p i51 i27 i35 h0 h1 _) ; finalize.
Qed.
Lemma l81 : s1 -> p84 (* ABS(gp_ideal, [0, 2]) *).
Proof.
 intros h0.
 assert (h1 := l82 h0).
 assert (h2 := l51 h0).
 apply t63. exact h1. exact h2.
Qed.
Lemma t64 : p84 -> p83.
Proof.
 intros h0.
 refine (float_absolute_wide_ne _ _ _gp_ideal i35 i50 h0 _) ; finalize.
Qed.
Lemma l80 : s1 -> p83 (* BND(gp - gp_ideal, [-1.11022e-16, 1.11022e-16]) *).
Proof.
 intros h0.
 assert (h1 := l81 h0).
 apply t64. exact h1.
Qed.
Notation p87 := (BND r75 i50). (* BND(dq - dq_ideal, [-1.11022e-16, 1.11022e-16]) *)
Notation p88 := (ABS _dq_ideal i35). (* ABS(dq_ideal, [0, 2]) *)
Lemma t65 : p49 -> p57 -> p88.
Proof.
 intros h0 h1.
 refine (mul_aa _delta _q i30 i35 i35 h0 h1 _) ; finalize.
Qed.
Lemma l84 : s1 -> p88 (* ABS(dq_ideal, [0, 2]) *).
Proof.
 intros h0.
 assert (h1 := l50 h0).
 assert (h2 := l55 h0).
 apply t65. exact h1. exact h2.
Qed.
Lemma t66 : p88 -> p87.
Proof.
 intros h0.
 refine (float_absolute_wide_ne _ _ _dq_ideal i35 i50 h0 _) ; finalize.
Qed.
Lemma l83 : s1 -> p87 (* BND(dq - dq_ideal, [-1.11022e-16, 1.11022e-16]) *).
Proof.
 intros h0.
 assert (h1 := l84 h0).
 apply t66. exact h1.
Qed.
Lemma t67 : p83 -> p87 -> p82.
Proof.
 intros h0 h1.
 refine (add r74 r75 i50 i50 i47 h0 h1 _) ; finalize.
Qed.
Lemma l79 : s1 -> p82 (* BND(gp - gp_ideal + (dq - dq_ideal), [-2.22045e-16, 2.22045e-16]) *).
Proof.
 intros h0.
 assert (h1 := l80 h0).
 assert (h2 := l83 h0).
 apply t67. exact h1. exact h2.
Qed.
Lemma t68 : p82 -> p81.
Proof.
 intros h0.
 refine (add_mibs _ _ _ _ i47 h0) ; finalize.
Qed.
Lemma l78 : s1 -> p81 (* BND(gp + dq - q1_ideal, [-2.22045e-16, 2.22045e-16]) *).
Proof.
 intros h0.
 assert (h1 := l79 h0).
 apply t68. exact h1.
Qed.
Lemma t69 : p78 -> p81 -> p77.
Proof.
 intros h0 h1.
 refine (add r71 r72 i47 i47 i31 h0 h1 _) ; finalize.
Qed.
Lemma l75 : s1 -> p77 (* BND(q1 - (gp + dq) + (gp + dq - q1_ideal), [-4.44089e-16, 4.44089e-16]) *).
Proof.
 intros h0.
 assert (h1 := l76 h0).
 assert (h2 := l78 h0).
 apply t69. exact h1. exact h2.
Qed.
Lemma t70 : p77 -> p76.
Proof.
 intros h0.
 refine (sub_xals _ _ _ i31 h0) ; finalize.
Qed.
Lemma l74 : s1 -> p76 (* BND(q1 - q1_ideal, [-4.44089e-16, 4.44089e-16]) *).
Proof.
 intros h0.
 assert (h1 := l75 h0).
 apply t70. exact h1.
Qed.
Definition f75 := Float2 (-124041857709758287) (-109).
Definition f76 := Float2 (124041857709758287) (-109).
Definition i52 := makepairF f75 f76.
Notation p89 := (BND r44 i52). (* BND(q1_ideal - q_exact, [-1.91117e-16, 1.91117e-16]) *)
Notation p90 := (BND r52 i52). (* BND(1653192778717867398717027865407 / 696347988586361041328261577891668148137807052800 * p + -26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120 * q, [-1.91117e-16, 1.91117e-16]) *)
Definition f77 := Float2 (-34284412897917959) (-110).
Definition f78 := Float2 (34284412897917959) (-110).
Definition i53 := makepairF f77 f78.
Notation p91 := (BND r53 i53). (* BND(1653192778717867398717027865407 / 696347988586361041328261577891668148137807052800 * p, [-2.64118e-17, 2.64118e-17]) *)
Definition f79 := Float2 (1) (-59).
Definition f80 := Float2 (24653959836705049) (-113).
Definition i54 := makepairF f79 f80.
Notation p92 := (BND r54 i54). (* BND(1653192778717867398717027865407 / 696347988586361041328261577891668148137807052800, [1.73472e-18, 2.37409e-18]) *)
Definition f81 := Float2 (1) (100).
Definition f82 := Float2 (23493282394580709) (46).
Definition i55 := makepairF f81 f82.
Notation p93 := (BND r55 i55). (* BND(1653192778717867398717027865407, [1.26765e+30, 1.65319e+30]) *)
Lemma t71 : p93.
Proof.
 refine (constant1 _ i55 _) ; finalize.
Qed.
Lemma l89 : s1 -> p93 (* BND(1653192778717867398717027865407, [1.26765e+30, 1.65319e+30]) *).
Proof.
 intros h0.
 apply t71.
Qed.
Definition f83 := Float2 (274660852312533783) (101).
Definition f84 := Float2 (1) (159).
Definition i56 := makepairF f83 f84.
Notation p94 := (BND r56 i56). (* BND(696347988586361041328261577891668148137807052800, [6.96348e+47, 7.30751e+47]) *)
Lemma t72 : p94.
Proof.
 refine (constant1 _ i56 _) ; finalize.
Qed.
Lemma l90 : s1 -> p94 (* BND(696347988586361041328261577891668148137807052800, [6.96348e+47, 7.30751e+47]) *).
Proof.
 intros h0.
 apply t72.
Qed.
Lemma t73 : p93 -> p94 -> p92.
Proof.
 intros h0 h1.
 refine (div_pp r55 r56 i55 i56 i54 h0 h1 _) ; finalize.
Qed.
Lemma l88 : s1 -> p92 (* BND(1653192778717867398717027865407 / 696347988586361041328261577891668148137807052800, [1.73472e-18, 2.37409e-18]) *).
Proof.
 intros h0.
 assert (h1 := l89 h0).
 assert (h2 := l90 h0).
 apply t73. exact h1. exact h2.
Qed.
Lemma t74 : p92 -> p1 -> p91.
Proof.
 intros h0 h1.
 refine (mul_po r54 _p i54 i1 i53 h0 h1 _) ; finalize.
Qed.
Lemma l87 : s1 -> p91 (* BND(1653192778717867398717027865407 / 696347988586361041328261577891668148137807052800 * p, [-2.64118e-17, 2.64118e-17]) *).
Proof.
 intros h0.
 assert (h1 := l88 h0).
 assert (h2 := l15 h0).
 apply t74. exact h1. exact h2.
Qed.
Definition f85 := Float2 (-213799302521598615) (-110).
Definition f86 := Float2 (213799302521598615) (-110).
Definition i57 := makepairF f85 f86.
Notation p95 := (BND r57 i57). (* BND(-26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120 * q, [-1.64705e-16, 1.64705e-16]) *)
Lemma t75 : p62 -> p2 -> p95.
Proof.
 intros h0 h1.
 refine (mul_no r47 _q i39 i2 i57 h0 h1 _) ; finalize.
Qed.
Lemma l91 : s1 -> p95 (* BND(-26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120 * q, [-1.64705e-16, 1.64705e-16]) *).
Proof.
 intros h0.
 assert (h1 := l59 h0).
 assert (h2 := l21 h0).
 apply t75. exact h1. exact h2.
Qed.
Lemma t76 : p91 -> p95 -> p90.
Proof.
 intros h0 h1.
 refine (add r53 r57 i53 i57 i52 h0 h1 _) ; finalize.
Qed.
Lemma l86 : s1 -> p90 (* BND(1653192778717867398717027865407 / 696347988586361041328261577891668148137807052800 * p + -26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120 * q, [-1.91117e-16, 1.91117e-16]) *).
Proof.
 intros h0.
 assert (h1 := l87 h0).
 assert (h2 := l91 h0).
 apply t76. exact h1. exact h2.
Qed.
Notation p96 := (REL r44 r52 i46). (* REL(q1_ideal - q_exact, 1653192778717867398717027865407 / 696347988586361041328261577891668148137807052800 * p + -26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120 * q, [0, 0]) *)
Notation p97 := (r44 = r52). (* EQL(q1_ideal - q_exact, 1653192778717867398717027865407 / 696347988586361041328261577891668148137807052800 * p + -26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120 * q) *)
Lemma t77 : p97.
Proof.
 refine (b4) ; finalize.
Qed.
Lemma l93 : s1 -> p97 (* EQL(q1_ideal - q_exact, 1653192778717867398717027865407 / 696347988586361041328261577891668148137807052800 * p + -26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120 * q) *).
Proof.
 intros h0.
 apply t77.
Qed.
Notation p98 := (REL r52 r52 i46). (* REL(1653192778717867398717027865407 / 696347988586361041328261577891668148137807052800 * p + -26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120 * q, 1653192778717867398717027865407 / 696347988586361041328261577891668148137807052800 * p + -26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120 * q, [0, 0]) *)
Lemma t78 : p98.
Proof.
 refine (rel_refl r52 i46 _) ; finalize.
Qed.
Lemma l94 : s1 -> p98 (* REL(1653192778717867398717027865407 / 696347988586361041328261577891668148137807052800 * p + -26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120 * q, 1653192778717867398717027865407 / 696347988586361041328261577891668148137807052800 * p + -26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120 * q, [0, 0]) *).
Proof.
 intros h0.
 apply t78.
Qed.
Lemma t79 : p97 -> p98 -> p96.
Proof.
 intros h0 h1.
 refine (rel_rewrite_1 r44 r52 r52 i46 h0 h1) ; finalize.
Qed.
Lemma l92 : s1 -> p96 (* REL(q1_ideal - q_exact, 1653192778717867398717027865407 / 696347988586361041328261577891668148137807052800 * p + -26902437575106681925807266903878992704715617 / 306257084171653319081306918663994503898804694316456471429120 * q, [0, 0]) *).
Proof.
 intros h0.
 assert (h1 := l93 h0).
 assert (h2 := l94 h0).
 apply t79. exact h1. exact h2.
Qed.
Lemma t80 : p90 -> p96 -> p89.
Proof.
 intros h0 h1.
 refine (bnd_of_bnd_rel_o r44 r52 i52 i46 i52 h0 h1 _) ; finalize.
Qed.
Lemma l85 : s1 -> p89 (* BND(q1_ideal - q_exact, [-1.91117e-16, 1.91117e-16]) *).
Proof.
 intros h0.
 assert (h1 := l86 h0).
 assert (h2 := l92 h0).
 apply t80. exact h1. exact h2.
Qed.
Lemma t81 : p76 -> p89 -> p75.
Proof.
 intros h0 h1.
 refine (add r42 r44 i31 i52 i4 h0 h1 _) ; finalize.
Qed.
Lemma l73 : s1 -> p75 (* BND(q1 - q1_ideal + (q1_ideal - q_exact), [-6.35206e-16, 6.35206e-16]) *).
Proof.
 intros h0.
 assert (h1 := l74 h0).
 assert (h2 := l85 h0).
 apply t81. exact h1. exact h2.
Qed.
Notation p99 := (REL r27 r41 i46). (* REL(q1 - q_exact, q1 - q1_ideal + (q1_ideal - q_exact), [0, 0]) *)
Notation p100 := (r27 = r41). (* EQL(q1 - q_exact, q1 - q1_ideal + (q1_ideal - q_exact)) *)
Lemma t82 : p100.
Proof.
 refine (b2) ; finalize.
Qed.
Lemma l96 : s1 -> p100 (* EQL(q1 - q_exact, q1 - q1_ideal + (q1_ideal - q_exact)) *).
Proof.
 intros h0.
 apply t82.
Qed.
Notation p101 := (REL r41 r41 i46). (* REL(q1 - q1_ideal + (q1_ideal - q_exact), q1 - q1_ideal + (q1_ideal - q_exact), [0, 0]) *)
Lemma t83 : p101.
Proof.
 refine (rel_refl r41 i46 _) ; finalize.
Qed.
Lemma l97 : s1 -> p101 (* REL(q1 - q1_ideal + (q1_ideal - q_exact), q1 - q1_ideal + (q1_ideal - q_exact), [0, 0]) *).
Proof.
 intros h0.
 apply t83.
Qed.
Lemma t84 : p100 -> p101 -> p99.
Proof.
 intros h0 h1.
 refine (rel_rewrite_1 r27 r41 r41 i46 h0 h1) ; finalize.
Qed.
Lemma l95 : s1 -> p99 (* REL(q1 - q_exact, q1 - q1_ideal + (q1_ideal - q_exact), [0, 0]) *).
Proof.
 intros h0.
 assert (h1 := l96 h0).
 assert (h2 := l97 h0).
 apply t84. exact h1. exact h2.
Qed.
Lemma t85 : p75 -> p99 -> p4.
Proof.
 intros h0 h1.
 refine (bnd_of_bnd_rel_o r27 r41 i4 i46 i4 h0 h1 _) ; finalize.
Qed.
Lemma l72 : s1 -> p4 (* BND(q1 - q_exact, [-6.35206e-16, 6.35206e-16]) *).
Proof.
 intros h0.
 assert (h1 := l73 h0).
 assert (h2 := l95 h0).
 apply t85. exact h1. exact h2.
Qed.
Lemma l1 : s1 -> False.
Proof.
 intros h0.
 assert (h1 := l2 h0).
 assert (h2 := l72 h0).
 refine (simplify (Tatom false (Abnd 0%nat i4)) Tfalse (Abnd 0%nat i4) (List.cons r27 List.nil) h2 h1 _) ; finalize.
Qed.
End Generated_by_Gappa.
End Gappa_N10.

Module Lifting_N10.
(* The lifting lemma of phi3-matrix in double (simpson-verify, issue 29): Phi, the invariant form Q and the one-step
   bound (Bp, Bq) are the harness's, exactly; Bp and Bq are Gappa's bound, proved in its own certificate.
   The float iterate is y_(k+1) = Phi y_k + e_k with |e_k| <= (Bp, Bq) while y_k stays in the box; the error
   d_k = y_k - Phi^k y_0 then obeys d_(k+1) = Phi d_k + e_k, and sqrt(Q(d_n)) <= n eps. *)
Open Scope R_scope.

Definition a := (247760988533536771305687694478496380154277693914865356389217 / 306257084171653319081306918663994503898804694316456471429120).
Definition b := (-53784815726555854523937747366679286727675529322959010423996723531036817249585608705484433 / 14558511621537888898126202167474500637236590474581529455778362919655804383322842534510592).
Definition c := (1807641825769423359468802491501 / 19327539251999843498371389135850).
Definition d := (247760988533536771305687694478496380154277693914865356389217 / 306257084171653319081306918663994503898804694316456471429120).
Definition wp := (1 / 1).
Definition wq := (1344620393163896363098443684166982168191888233073975260599918088275920431239640217637110825 / 34040254924484386204803571210225647169656942870274671704515903447811402264688293144690688).
Definition Bp := (643630877231412395 / 162259276829213363391578010288128).
Definition Bq := (412272233861470031 / 649037107316853453566312041152512).
Definition eps := (891767682444737 / 158456325028528675187087900672).

Definition Q (x y : R) := wp * x * x + wq * y * y.

Lemma Q_nonneg : forall x y, 0 <= Q x y.
Proof. intros. unfold Q, wp, wq. nra. Qed.

Lemma invariant : forall x y, Q (a * x + b * y) (c * x + d * y) = Q x y.
Proof. intros. unfold Q, a, b, c, d, wp, wq. field. Qed.

Lemma one_step : forall ex ey, -Bp <= ex <= Bp -> -Bq <= ey <= Bq -> Q ex ey <= eps * eps.
Proof. intros ex ey Hx Hy. unfold Q, wp, wq, Bp, Bq, eps in *. nra. Qed.

Lemma cauchy : forall x1 y1 x2 y2, wp * x1 * x2 + wq * y1 * y2 <= sqrt (Q x1 y1) * sqrt (Q x2 y2).
Proof.
  intros. rewrite <- sqrt_mult by apply Q_nonneg.
  destruct (Rle_or_lt (wp * x1 * x2 + wq * y1 * y2) 0) as [H | H].
  - apply Rle_trans with 0; [exact H | apply sqrt_pos].
  - apply Rsqr_incr_0_var; [| apply sqrt_pos].
    rewrite Rsqr_sqrt by (apply Rmult_le_pos; apply Q_nonneg).
    assert (W : 0 <= wp * wq) by (unfold wp, wq; lra).
    pose proof (Rle_0_sqr (x1 * y2 - x2 * y1)) as Sq. unfold Rsqr in Sq.
    assert (0 <= wp * wq * ((x1 * y2 - x2 * y1) * (x1 * y2 - x2 * y1))) by (apply Rmult_le_pos; assumption).
    unfold Rsqr, Q. nra.
Qed.

Lemma triangle : forall x1 y1 x2 y2, sqrt (Q (x1 + x2) (y1 + y2)) <= sqrt (Q x1 y1) + sqrt (Q x2 y2).
Proof.
  intros. apply Rsqr_incr_0_var; [| apply Rplus_le_le_0_compat; apply sqrt_pos].
  rewrite Rsqr_sqrt by apply Q_nonneg.
  pose proof (cauchy x1 y1 x2 y2) as C.
  pose proof (sqrt_sqrt (Q x1 y1) (Q_nonneg x1 y1)) as S1.
  pose proof (sqrt_sqrt (Q x2 y2) (Q_nonneg x2 y2)) as S2.
  unfold Rsqr. unfold Q in *. nra.
Qed.

Theorem lifting : forall (dp dq ep eq : nat -> R),
  dp 0%nat = 0 -> dq 0%nat = 0 ->
  (forall k, dp (S k) = a * dp k + b * dq k + ep k) ->
  (forall k, dq (S k) = c * dp k + d * dq k + eq k) ->
  (forall k, -Bp <= ep k <= Bp /\ -Bq <= eq k <= Bq) ->
  forall n, sqrt (Q (dp n) (dq n)) <= INR n * eps.
Proof.
  intros dp dq ep eq H0p H0q Hp Hq He n. induction n as [| n IH].
  - rewrite H0p, H0q. unfold Q. simpl. replace (wp * 0 * 0 + wq * 0 * 0) with 0 by ring. rewrite sqrt_0. lra.
  - rewrite Hp, Hq, S_INR.
    eapply Rle_trans; [apply triangle |].
    rewrite invariant.
    assert (sqrt (Q (ep n) (eq n)) <= eps).
    { destruct (He n) as [Hx Hy].
      rewrite <- (sqrt_square eps) by (unfold eps; lra).
      apply sqrt_le_1_alt. apply one_step; assumption. }
    lra.
Qed.
End Lifting_N10.

Module Gappa_N20.
Section Generated_by_Gappa.
Notation _delta := (float2R (Float2 (8566352578442851) (-53))).
Variable _p_input : R.
Notation _p := ((rounding_float rndNE (53)%positive (-1074)%Z) _p_input).
Notation _ap_ideal := ((_delta * _p)%R).
Notation _ap := ((rounding_float rndNE (53)%positive (-1074)%Z) _ap_ideal).
Notation _beta := (float2R (Float2 (-4372208577176417) (-51))).
Variable _q_input : R.
Notation _q := ((rounding_float rndNE (53)%positive (-1074)%Z) _q_input).
Notation _bq_ideal := ((_beta * _q)%R).
Notation _bq := ((rounding_float rndNE (53)%positive (-1074)%Z) _bq_ideal).
Notation r3 := ((_ap + _bq)%R).
Notation _p1 := ((rounding_float rndNE (53)%positive (-1074)%Z) r3).
Notation r17 := (Float1 (4603719609199889721500218209637141174193549725516937316940641)).
Notation r18 := (Float1 (4840638936269341396294642382423593871270175513277109765144576)).
Notation _delta_exact := ((r17 / r18)%R).
Notation r15 := ((_delta_exact * _p)%R).
Notation r21 := (Float1 (-4467912064472210654272016230342243611753646281573833613883785510285988932817859942208192725)).
Notation r22 := (Float1 (2301089569893738191214049136294392848876640076138894889705378020928991397008229047222665216)).
Notation _beta_exact := ((r21 / r22)%R).
Notation r19 := ((_beta_exact * _q)%R).
Notation _p_exact := ((r15 + r19)%R).
Notation r1 := ((_p1 - _p_exact)%R).
Notation _p1_ideal := ((_ap_ideal + _bq_ideal)%R).
Notation r24 := ((_p1 - _p1_ideal)%R).
Notation r26 := ((_p1_ideal - _p_exact)%R).
Notation r23 := ((r24 + r26)%R).
Lemma a1 : r1 = r23.
Proof. first [ring | unfold float2R, Float1, Defs.F2R; simpl; unfold Z.pow_pos; simpl; field]. Qed.
Lemma b1 : r1 = r23.
 apply a1.
Qed.
Notation _gamma := (float2R (Float2 (7087714851348987) (-57))).
Notation _gp_ideal := ((_gamma * _p)%R).
Notation _gp := ((rounding_float rndNE (53)%positive (-1074)%Z) _gp_ideal).
Notation _dq_ideal := ((_delta * _q)%R).
Notation _dq := ((rounding_float rndNE (53)%positive (-1074)%Z) _dq_ideal).
Notation r29 := ((_gp + _dq)%R).
Notation _q1 := ((rounding_float rndNE (53)%positive (-1074)%Z) r29).
Notation r38 := (Float1 (7512069526796455666203966915693)).
Notation r39 := (Float1 (152743632524540333131446066755540)).
Notation _gamma_exact := ((r38 / r39)%R).
Notation r36 := ((_gamma_exact * _p)%R).
Notation r40 := ((_delta_exact * _q)%R).
Notation _q_exact := ((r36 + r40)%R).
Notation r27 := ((_q1 - _q_exact)%R).
Notation _q1_ideal := ((_gp_ideal + _dq_ideal)%R).
Notation r42 := ((_q1 - _q1_ideal)%R).
Notation r44 := ((_q1_ideal - _q_exact)%R).
Notation r41 := ((r42 + r44)%R).
Lemma a2 : r27 = r41.
Proof. first [ring | unfold float2R, Float1, Defs.F2R; simpl; unfold Z.pow_pos; simpl; field]. Qed.
Lemma b2 : r27 = r41.
 apply a2.
Qed.
Notation r48 := (Float1 (-607398879457070813777175880614497980136962913)).
Notation r47 := ((r48 / r18)%R).
Notation r46 := ((r47 * _p)%R).
Notation r51 := (Float1 (570419849984716187108541389157035433662294559263261888455660546024551170261)).
Notation r50 := ((r51 / r22)%R).
Notation r49 := ((r50 * _q)%R).
Notation r45 := ((r46 + r49)%R).
Lemma a3 : r26 = r45.
Proof. first [ring | unfold float2R, Float1, Defs.F2R; simpl; unfold Z.pow_pos; simpl; field]. Qed.
Lemma b3 : r26 = r45.
 apply a3.
Qed.
Notation r55 := (Float1 (-36845085767445699368127421840329)).
Notation r56 := (Float1 (5503169332165886540104386747797882289057924382720)).
Notation r54 := ((r55 / r56)%R).
Notation r53 := ((r54 * _p)%R).
Notation r57 := ((r47 * _q)%R).
Notation r52 := ((r53 + r57)%R).
Lemma a4 : r44 = r52.
Proof. first [ring | unfold float2R, Float1, Defs.F2R; simpl; unfold Z.pow_pos; simpl; field]. Qed.
Lemma b4 : r44 = r52.
 apply a4.
Qed.
Definition f1 := Float2 (-89) (-3).
Definition f2 := Float2 (89) (-3).
Definition i1 := makepairF f1 f2.
Notation p1 := (BND _p i1). (* BND(p, [-11.125, 11.125]) *)
Definition f3 := Float2 (-15) (-3).
Definition f4 := Float2 (15) (-3).
Definition i2 := makepairF f3 f4.
Notation p2 := (BND _q i2). (* BND(q, [-1.875, 1.875]) *)
Definition s2 := (p1 /\ p2).
Definition f5 := Float2 (-626183230779878159) (-107).
Definition f6 := Float2 (626183230779878159) (-107).
Definition i3 := makepairF f5 f6.
Notation p3 := (BND r1 i3). (* BND(p1 - p_exact, [-3.85915e-15, 3.85915e-15]) *)
Definition s10 := (not p3).
Definition f7 := Float2 (-906491898205906241) (-110).
Definition f8 := Float2 (906491898205906241) (-110).
Definition i4 := makepairF f7 f8.
Notation p4 := (BND r27 i4). (* BND(q1 - q_exact, [-6.98336e-16, 6.98336e-16]) *)
Definition s11 := (not p4).
Definition s9 := (s10 \/ s11).
Notation r58 := ((Rabs _ap)%R).
Definition f9 := Float2 (0) (0).
Definition f10 := Float2 (9007199254740991) (971).
Definition i5 := makepairF f9 f10.
Notation p5 := (BND r58 i5). (* BND(|ap|, [0, 1.79769e+308]) *)
Definition s12 := (not p5).
Definition s8 := (s9 \/ s12).
Notation r59 := ((Rabs _bq)%R).
Notation p6 := (BND r59 i5). (* BND(|bq|, [0, 1.79769e+308]) *)
Definition s13 := (not p6).
Definition s7 := (s8 \/ s13).
Notation r60 := ((Rabs _p1)%R).
Notation p7 := (BND r60 i5). (* BND(|p1|, [0, 1.79769e+308]) *)
Definition s14 := (not p7).
Definition s6 := (s7 \/ s14).
Notation r61 := ((Rabs _gp)%R).
Notation p8 := (BND r61 i5). (* BND(|gp|, [0, 1.79769e+308]) *)
Definition s15 := (not p8).
Definition s5 := (s6 \/ s15).
Notation r62 := ((Rabs _dq)%R).
Notation p9 := (BND r62 i5). (* BND(|dq|, [0, 1.79769e+308]) *)
Definition s16 := (not p9).
Definition s4 := (s5 \/ s16).
Notation r63 := ((Rabs _q1)%R).
Notation p10 := (BND r63 i5). (* BND(|q1|, [0, 1.79769e+308]) *)
Definition s17 := (not p10).
Definition s3 := (s4 \/ s17).
Definition s1 := (s2 /\ s3).
Definition s18 := (s9 \/ s17).
Definition s20 := (s9 \/ s14).
Definition s19 := (s20 \/ s17).
Definition s22 := (s20 \/ s15).
Definition s21 := (s22 \/ s17).
Definition s26 := (s9 \/ s13).
Definition s25 := (s26 \/ s14).
Definition s24 := (s25 \/ s15).
Definition s23 := (s24 \/ s17).
Definition s28 := (s24 \/ s16).
Definition s27 := (s28 \/ s17).
Lemma l9 : s1 -> s3.
Proof.
 intros h0.
 assert (h1 := h0).
 exact (proj2 h1).
Qed.
Definition f11 := Float2 (5956292027198545) (-49).
Definition i6 := makepairF f9 f11.
Notation p11 := (BND r58 i6). (* BND(|ap|, [0, 10.5805]) *)
Notation p12 := (ABS _ap i6). (* ABS(ap, [0, 10.5805]) *)
Definition f12 := Float2 (-5956292027198545) (-49).
Definition i7 := makepairF f12 f11.
Notation p13 := (BND _ap i7). (* BND(ap, [-10.5805, 10.5805]) *)
Notation p14 := (BND _ap_ideal i7). (* BND(ap_ideal, [-10.5805, 10.5805]) *)
Definition f13 := Float2 (1) (-1).
Definition f14 := Float2 (8566352578442851) (-53).
Definition i8 := makepairF f13 f14.
Notation p15 := (BND _delta i8). (* BND(delta, [0.5, 0.951056]) *)
Lemma t1 : p15.
Proof.
 refine (constant2 _ i8 _) ; finalize.
Qed.
Lemma l14 : s1 -> p15 (* BND(delta, [0.5, 0.951056]) *).
Proof.
 intros h0.
 apply t1.
Qed.
Lemma l16 : s1 -> s2.
Proof.
 intros h0.
 assert (h1 := h0).
 exact (proj1 h1).
Qed.
Lemma l15 : s1 -> p1 (* BND(p, [-11.125, 11.125]) *).
Proof.
 intros h0.
 assert (h1 := l16 h0).
 exact (proj1 h1).
Qed.
Lemma t2 : p15 -> p1 -> p14.
Proof.
 intros h0 h1.
 refine (mul_po _delta _p i8 i1 i7 h0 h1 _) ; finalize.
Qed.
Lemma l13 : s1 -> p14 (* BND(ap_ideal, [-10.5805, 10.5805]) *).
Proof.
 intros h0.
 assert (h1 := l14 h0).
 assert (h2 := l15 h0).
 apply t2. exact h1. exact h2.
Qed.
Lemma t3 : p14 -> p13.
Proof.
 intros h0.
 refine (float_round_ne _ _ _ap_ideal i7 i7 h0 _) ; finalize.
Qed.
Lemma l12 : s1 -> p13 (* BND(ap, [-10.5805, 10.5805]) *).
Proof.
 intros h0.
 assert (h1 := l13 h0).
 apply t3. exact h1.
Qed.
Lemma t4 : p13 -> p12.
Proof.
 intros h0.
 refine (abs_of_bnd_o _ap i7 i6 h0 _) ; finalize.
Qed.
Lemma l11 : s1 -> p12 (* ABS(ap, [0, 10.5805]) *).
Proof.
 intros h0.
 assert (h1 := l12 h0).
 apply t4. exact h1.
Qed.
Lemma t5 : p12 -> p11.
Proof.
 intros h0.
 refine (uabs_of_abs _ap i6 h0) ; finalize.
Qed.
Lemma l10 : s1 -> p11 (* BND(|ap|, [0, 10.5805]) *).
Proof.
 intros h0.
 assert (h1 := l11 h0).
 apply t5. exact h1.
Qed.
Lemma l8 : s1 -> s27.
Proof.
 intros h0.
 assert (h1 := l9 h0).
 assert (h2 := l10 h0).
 refine (simplify (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 2%nat i5))) (Tatom false (Abnd 3%nat i5))) (Tatom false (Abnd 4%nat i5))) (Tatom false (Abnd 5%nat i5))) (Tatom false (Abnd 6%nat i5))) (Tatom false (Abnd 7%nat i5))) (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 3%nat i5))) (Tatom false (Abnd 4%nat i5))) (Tatom false (Abnd 5%nat i5))) (Tatom false (Abnd 6%nat i5))) (Tatom false (Abnd 7%nat i5))) (Abnd 2%nat i6) (List.cons r1 (List.cons r27 (List.cons r58 (List.cons r59 (List.cons r60 (List.cons r61 (List.cons r62 (List.cons r63 List.nil)))))))) h2 h1 _) ; finalize.
Qed.
Definition f15 := Float2 (8030955542290173) (-52).
Definition i9 := makepairF f9 f15.
Notation p16 := (BND r62 i9). (* BND(|dq|, [0, 1.78323]) *)
Notation p17 := (ABS _dq i9). (* ABS(dq, [0, 1.78323]) *)
Definition f16 := Float2 (-8030955542290173) (-52).
Definition i10 := makepairF f16 f15.
Notation p18 := (BND _dq i10). (* BND(dq, [-1.78323, 1.78323]) *)
Notation p19 := (BND _dq_ideal i10). (* BND(dq_ideal, [-1.78323, 1.78323]) *)
Lemma l21 : s1 -> p2 (* BND(q, [-1.875, 1.875]) *).
Proof.
 intros h0.
 assert (h1 := l16 h0).
 exact (proj2 h1).
Qed.
Lemma t6 : p15 -> p2 -> p19.
Proof.
 intros h0 h1.
 refine (mul_po _delta _q i8 i2 i10 h0 h1 _) ; finalize.
Qed.
Lemma l20 : s1 -> p19 (* BND(dq_ideal, [-1.78323, 1.78323]) *).
Proof.
 intros h0.
 assert (h1 := l14 h0).
 assert (h2 := l21 h0).
 apply t6. exact h1. exact h2.
Qed.
Lemma t7 : p19 -> p18.
Proof.
 intros h0.
 refine (float_round_ne _ _ _dq_ideal i10 i10 h0 _) ; finalize.
Qed.
Lemma l19 : s1 -> p18 (* BND(dq, [-1.78323, 1.78323]) *).
Proof.
 intros h0.
 assert (h1 := l20 h0).
 apply t7. exact h1.
Qed.
Lemma t8 : p18 -> p17.
Proof.
 intros h0.
 refine (abs_of_bnd_o _dq i10 i9 h0 _) ; finalize.
Qed.
Lemma l18 : s1 -> p17 (* ABS(dq, [0, 1.78323]) *).
Proof.
 intros h0.
 assert (h1 := l19 h0).
 apply t8. exact h1.
Qed.
Lemma t9 : p17 -> p16.
Proof.
 intros h0.
 refine (uabs_of_abs _dq i9 h0) ; finalize.
Qed.
Lemma l17 : s1 -> p16 (* BND(|dq|, [0, 1.78323]) *).
Proof.
 intros h0.
 assert (h1 := l18 h0).
 apply t9. exact h1.
Qed.
Lemma l7 : s1 -> s23.
Proof.
 intros h0.
 assert (h1 := l8 h0).
 assert (h2 := l17 h0).
 refine (simplify (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 2%nat i5))) (Tatom false (Abnd 3%nat i5))) (Tatom false (Abnd 4%nat i5))) (Tatom false (Abnd 5%nat i5))) (Tatom false (Abnd 6%nat i5))) (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 2%nat i5))) (Tatom false (Abnd 3%nat i5))) (Tatom false (Abnd 4%nat i5))) (Tatom false (Abnd 6%nat i5))) (Abnd 5%nat i9) (List.cons r1 (List.cons r27 (List.cons r59 (List.cons r60 (List.cons r61 (List.cons r62 (List.cons r63 List.nil))))))) h2 h1 _) ; finalize.
Qed.
Definition f17 := Float2 (4098945541102891) (-50).
Definition i11 := makepairF f9 f17.
Notation p20 := (BND r59 i11). (* BND(|bq|, [0, 3.64059]) *)
Notation p21 := (ABS _bq i11). (* ABS(bq, [0, 3.64059]) *)
Definition f18 := Float2 (-4098945541102891) (-50).
Definition i12 := makepairF f18 f17.
Notation p22 := (BND _bq i12). (* BND(bq, [-3.64059, 3.64059]) *)
Notation p23 := (BND _bq_ideal i12). (* BND(bq_ideal, [-3.64059, 3.64059]) *)
Definition f19 := Float2 (-4372208577176417) (-51).
Definition f20 := Float2 (-1) (0).
Definition i13 := makepairF f19 f20.
Notation p24 := (BND _beta i13). (* BND(beta, [-1.94165, -1]) *)
Lemma t10 : p24.
Proof.
 refine (constant2 _ i13 _) ; finalize.
Qed.
Lemma l26 : s1 -> p24 (* BND(beta, [-1.94165, -1]) *).
Proof.
 intros h0.
 apply t10.
Qed.
Lemma t11 : p24 -> p2 -> p23.
Proof.
 intros h0 h1.
 refine (mul_no _beta _q i13 i2 i12 h0 h1 _) ; finalize.
Qed.
Lemma l25 : s1 -> p23 (* BND(bq_ideal, [-3.64059, 3.64059]) *).
Proof.
 intros h0.
 assert (h1 := l26 h0).
 assert (h2 := l21 h0).
 apply t11. exact h1. exact h2.
Qed.
Lemma t12 : p23 -> p22.
Proof.
 intros h0.
 refine (float_round_ne _ _ _bq_ideal i12 i12 h0 _) ; finalize.
Qed.
Lemma l24 : s1 -> p22 (* BND(bq, [-3.64059, 3.64059]) *).
Proof.
 intros h0.
 assert (h1 := l25 h0).
 apply t12. exact h1.
Qed.
Lemma t13 : p22 -> p21.
Proof.
 intros h0.
 refine (abs_of_bnd_o _bq i12 i11 h0 _) ; finalize.
Qed.
Lemma l23 : s1 -> p21 (* ABS(bq, [0, 3.64059]) *).
Proof.
 intros h0.
 assert (h1 := l24 h0).
 apply t13. exact h1.
Qed.
Lemma t14 : p21 -> p20.
Proof.
 intros h0.
 refine (uabs_of_abs _bq i11 h0) ; finalize.
Qed.
Lemma l22 : s1 -> p20 (* BND(|bq|, [0, 3.64059]) *).
Proof.
 intros h0.
 assert (h1 := l23 h0).
 apply t14. exact h1.
Qed.
Lemma l6 : s1 -> s21.
Proof.
 intros h0.
 assert (h1 := l7 h0).
 assert (h2 := l22 h0).
 refine (simplify (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 2%nat i5))) (Tatom false (Abnd 3%nat i5))) (Tatom false (Abnd 4%nat i5))) (Tatom false (Abnd 5%nat i5))) (Ttree false (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 3%nat i5))) (Tatom false (Abnd 4%nat i5))) (Tatom false (Abnd 5%nat i5))) (Abnd 2%nat i11) (List.cons r1 (List.cons r27 (List.cons r59 (List.cons r60 (List.cons r61 (List.cons r63 List.nil)))))) h2 h1 _) ; finalize.
Qed.
Definition f21 := Float2 (4928176732578593) (-53).
Definition i14 := makepairF f9 f21.
Notation p25 := (BND r61 i14). (* BND(|gp|, [0, 0.547138]) *)
Notation p26 := (ABS _gp i14). (* ABS(gp, [0, 0.547138]) *)
Definition f22 := Float2 (-4928176732578593) (-53).
Definition i15 := makepairF f22 f21.
Notation p27 := (BND _gp i15). (* BND(gp, [-0.547138, 0.547138]) *)
Notation p28 := (BND _gp_ideal i15). (* BND(gp_ideal, [-0.547138, 0.547138]) *)
Definition f23 := Float2 (1) (-5).
Definition f24 := Float2 (7087714851348987) (-57).
Definition i16 := makepairF f23 f24.
Notation p29 := (BND _gamma i16). (* BND(gamma, [0.03125, 0.0491809]) *)
Lemma t15 : p29.
Proof.
 refine (constant2 _ i16 _) ; finalize.
Qed.
Lemma l31 : s1 -> p29 (* BND(gamma, [0.03125, 0.0491809]) *).
Proof.
 intros h0.
 apply t15.
Qed.
Lemma t16 : p29 -> p1 -> p28.
Proof.
 intros h0 h1.
 refine (mul_po _gamma _p i16 i1 i15 h0 h1 _) ; finalize.
Qed.
Lemma l30 : s1 -> p28 (* BND(gp_ideal, [-0.547138, 0.547138]) *).
Proof.
 intros h0.
 assert (h1 := l31 h0).
 assert (h2 := l15 h0).
 apply t16. exact h1. exact h2.
Qed.
Lemma t17 : p28 -> p27.
Proof.
 intros h0.
 refine (float_round_ne _ _ _gp_ideal i15 i15 h0 _) ; finalize.
Qed.
Lemma l29 : s1 -> p27 (* BND(gp, [-0.547138, 0.547138]) *).
Proof.
 intros h0.
 assert (h1 := l30 h0).
 apply t17. exact h1.
Qed.
Lemma t18 : p27 -> p26.
Proof.
 intros h0.
 refine (abs_of_bnd_o _gp i15 i14 h0 _) ; finalize.
Qed.
Lemma l28 : s1 -> p26 (* ABS(gp, [0, 0.547138]) *).
Proof.
 intros h0.
 assert (h1 := l29 h0).
 apply t18. exact h1.
Qed.
Lemma t19 : p26 -> p25.
Proof.
 intros h0.
 refine (uabs_of_abs _gp i14 h0) ; finalize.
Qed.
Lemma l27 : s1 -> p25 (* BND(|gp|, [0, 0.547138]) *).
Proof.
 intros h0.
 assert (h1 := l28 h0).
 apply t19. exact h1.
Qed.
Lemma l5 : s1 -> s19.
Proof.
 intros h0.
 assert (h1 := l6 h0).
 assert (h2 := l27 h0).
 refine (simplify (Ttree false (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 2%nat i5))) (Tatom false (Abnd 3%nat i5))) (Tatom false (Abnd 4%nat i5))) (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 2%nat i5))) (Tatom false (Abnd 4%nat i5))) (Abnd 3%nat i14) (List.cons r1 (List.cons r27 (List.cons r60 (List.cons r61 (List.cons r63 List.nil))))) h2 h1 _) ; finalize.
Qed.
Definition f25 := Float2 (4002882398874995) (-48).
Definition i17 := makepairF f9 f25.
Notation p30 := (BND r60 i17). (* BND(|p1|, [0, 14.2211]) *)
Notation p31 := (ABS _p1 i17). (* ABS(p1, [0, 14.2211]) *)
Definition f26 := Float2 (-4002882398874995) (-48).
Definition i18 := makepairF f26 f25.
Notation p32 := (BND _p1 i18). (* BND(p1, [-14.2211, 14.2211]) *)
Definition f27 := Float2 (-16011529595499981) (-50).
Definition f28 := Float2 (16011529595499981) (-50).
Definition i19 := makepairF f27 f28.
Notation p33 := (BND r3 i19). (* BND(ap + bq, [-14.2211, 14.2211]) *)
Lemma t20 : p13 -> p22 -> p33.
Proof.
 intros h0 h1.
 refine (add _ap _bq i7 i12 i19 h0 h1 _) ; finalize.
Qed.
Lemma l35 : s1 -> p33 (* BND(ap + bq, [-14.2211, 14.2211]) *).
Proof.
 intros h0.
 assert (h1 := l12 h0).
 assert (h2 := l24 h0).
 apply t20. exact h1. exact h2.
Qed.
Lemma t21 : p33 -> p32.
Proof.
 intros h0.
 refine (float_round_ne _ _ r3 i19 i18 h0 _) ; finalize.
Qed.
Lemma l34 : s1 -> p32 (* BND(p1, [-14.2211, 14.2211]) *).
Proof.
 intros h0.
 assert (h1 := l35 h0).
 apply t21. exact h1.
Qed.
Lemma t22 : p32 -> p31.
Proof.
 intros h0.
 refine (abs_of_bnd_o _p1 i18 i17 h0 _) ; finalize.
Qed.
Lemma l33 : s1 -> p31 (* ABS(p1, [0, 14.2211]) *).
Proof.
 intros h0.
 assert (h1 := l34 h0).
 apply t22. exact h1.
Qed.
Lemma t23 : p31 -> p30.
Proof.
 intros h0.
 refine (uabs_of_abs _p1 i17 h0) ; finalize.
Qed.
Lemma l32 : s1 -> p30 (* BND(|p1|, [0, 14.2211]) *).
Proof.
 intros h0.
 assert (h1 := l33 h0).
 apply t23. exact h1.
Qed.
Lemma l4 : s1 -> s18.
Proof.
 intros h0.
 assert (h1 := l5 h0).
 assert (h2 := l32 h0).
 refine (simplify (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 2%nat i5))) (Tatom false (Abnd 3%nat i5))) (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 3%nat i5))) (Abnd 2%nat i17) (List.cons r1 (List.cons r27 (List.cons r60 (List.cons r63 List.nil)))) h2 h1 _) ; finalize.
Qed.
Definition f29 := Float2 (5247521954289735) (-51).
Definition i20 := makepairF f9 f29.
Notation p34 := (BND r63 i20). (* BND(|q1|, [0, 2.33037]) *)
Notation p35 := (ABS _q1 i20). (* ABS(q1, [0, 2.33037]) *)
Definition f30 := Float2 (-5247521954289735) (-51).
Definition i21 := makepairF f30 f29.
Notation p36 := (BND _q1 i21). (* BND(q1, [-2.33037, 2.33037]) *)
Notation p37 := (BND r29 i21). (* BND(gp + dq, [-2.33037, 2.33037]) *)
Definition f31 := Float2 (-2464088366289297) (-52).
Definition f32 := Float2 (2464088366289297) (-52).
Definition i22 := makepairF f31 f32.
Notation p38 := (BND _gp i22). (* BND(gp, [-0.547138, 0.547138]) *)
Lemma t24 : p38 -> p18 -> p37.
Proof.
 intros h0 h1.
 refine (add _gp _dq i22 i10 i21 h0 h1 _) ; finalize.
Qed.
Lemma l39 : s1 -> p37 (* BND(gp + dq, [-2.33037, 2.33037]) *).
Proof.
 intros h0.
 assert (h1 := l29 h0).
 assert (h2 := l19 h0).
 apply t24. refine (subset _gp i15 i22 h1 _) ; finalize. exact h2.
Qed.
Lemma t25 : p37 -> p36.
Proof.
 intros h0.
 refine (float_round_ne _ _ r29 i21 i21 h0 _) ; finalize.
Qed.
Lemma l38 : s1 -> p36 (* BND(q1, [-2.33037, 2.33037]) *).
Proof.
 intros h0.
 assert (h1 := l39 h0).
 apply t25. exact h1.
Qed.
Lemma t26 : p36 -> p35.
Proof.
 intros h0.
 refine (abs_of_bnd_o _q1 i21 i20 h0 _) ; finalize.
Qed.
Lemma l37 : s1 -> p35 (* ABS(q1, [0, 2.33037]) *).
Proof.
 intros h0.
 assert (h1 := l38 h0).
 apply t26. exact h1.
Qed.
Lemma t27 : p35 -> p34.
Proof.
 intros h0.
 refine (uabs_of_abs _q1 i20 h0) ; finalize.
Qed.
Lemma l36 : s1 -> p34 (* BND(|q1|, [0, 2.33037]) *).
Proof.
 intros h0.
 assert (h1 := l37 h0).
 apply t27. exact h1.
Qed.
Lemma l3 : s1 -> s9.
Proof.
 intros h0.
 assert (h1 := l4 h0).
 assert (h2 := l36 h0).
 refine (simplify (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 2%nat i5))) (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Abnd 2%nat i20) (List.cons r1 (List.cons r27 (List.cons r63 List.nil))) h2 h1 _) ; finalize.
Qed.
Notation p39 := (BND r23 i3). (* BND(p1 - p1_ideal + (p1_ideal - p_exact), [-3.85915e-15, 3.85915e-15]) *)
Definition f33 := Float2 (-9) (-52).
Definition f34 := Float2 (9) (-52).
Definition i23 := makepairF f33 f34.
Notation p40 := (BND r24 i23). (* BND(p1 - p1_ideal, [-1.9984e-15, 1.9984e-15]) *)
Notation r65 := ((_p1 - r3)%R).
Notation r66 := ((r3 - _p1_ideal)%R).
Notation r64 := ((r65 + r66)%R).
Notation p41 := (BND r64 i23). (* BND(p1 - (ap + bq) + (ap + bq - p1_ideal), [-1.9984e-15, 1.9984e-15]) *)
Definition f35 := Float2 (-1) (-50).
Definition f36 := Float2 (1) (-50).
Definition i24 := makepairF f35 f36.
Notation p42 := (BND r65 i24). (* BND(p1 - (ap + bq), [-8.88178e-16, 8.88178e-16]) *)
Definition f37 := Float2 (1) (4).
Definition i25 := makepairF f9 f37.
Notation p43 := (ABS r3 i25). (* ABS(ap + bq, [0, 16]) *)
Definition f38 := Float2 (-1) (4).
Definition i26 := makepairF f38 f37.
Notation p44 := (BND r3 i26). (* BND(ap + bq, [-16, 16]) *)
Lemma t28 : p44 -> p43.
Proof.
 intros h0.
 refine (abs_of_bnd_o r3 i26 i25 h0 _) ; finalize.
Qed.
Lemma l45 : s1 -> p43 (* ABS(ap + bq, [0, 16]) *).
Proof.
 intros h0.
 assert (h1 := l35 h0).
 apply t28. refine (subset r3 i19 i26 h1 _) ; finalize.
Qed.
Lemma t29 : p43 -> p42.
Proof.
 intros h0.
 refine (float_absolute_wide_ne _ _ r3 i25 i24 h0 _) ; finalize.
Qed.
Lemma l44 : s1 -> p42 (* BND(p1 - (ap + bq), [-8.88178e-16, 8.88178e-16]) *).
Proof.
 intros h0.
 assert (h1 := l45 h0).
 apply t29. exact h1.
Qed.
Definition f39 := Float2 (-5) (-52).
Definition f40 := Float2 (5) (-52).
Definition i27 := makepairF f39 f40.
Notation p45 := (BND r66 i27). (* BND(ap + bq - p1_ideal, [-1.11022e-15, 1.11022e-15]) *)
Notation r68 := ((_ap - _ap_ideal)%R).
Notation r69 := ((_bq - _bq_ideal)%R).
Notation r67 := ((r68 + r69)%R).
Notation p46 := (BND r67 i27). (* BND(ap - ap_ideal + (bq - bq_ideal), [-1.11022e-15, 1.11022e-15]) *)
Notation p47 := (BND r68 i24). (* BND(ap - ap_ideal, [-8.88178e-16, 8.88178e-16]) *)
Notation p48 := (ABS _ap_ideal i25). (* ABS(ap_ideal, [0, 16]) *)
Definition f41 := Float2 (1) (0).
Definition i28 := makepairF f13 f41.
Notation p49 := (ABS _delta i28). (* ABS(delta, [0.5, 1]) *)
Notation p50 := (BND _delta i28). (* BND(delta, [0.5, 1]) *)
Lemma t30 : p50 -> p49.
Proof.
 intros h0.
 refine (abs_of_bnd_p _delta i28 i28 h0 _) ; finalize.
Qed.
Lemma l50 : s1 -> p49 (* ABS(delta, [0.5, 1]) *).
Proof.
 intros h0.
 assert (h1 := l14 h0).
 apply t30. refine (subset _delta i8 i28 h1 _) ; finalize.
Qed.
Notation p51 := (ABS _p i25). (* ABS(p, [0, 16]) *)
Notation p52 := (BND _p i26). (* BND(p, [-16, 16]) *)
Lemma t31 : p52 -> p51.
Proof.
 intros h0.
 refine (abs_of_bnd_o _p i26 i25 h0 _) ; finalize.
Qed.
Lemma l51 : s1 -> p51 (* ABS(p, [0, 16]) *).
Proof.
 intros h0.
 assert (h1 := l15 h0).
 apply t31. refine (subset _p i1 i26 h1 _) ; finalize.
Qed.
Lemma t32 : p49 -> p51 -> p48.
Proof.
 intros h0 h1.
 refine (mul_aa _delta _p i28 i25 i25 h0 h1 _) ; finalize.
Qed.
Lemma l49 : s1 -> p48 (* ABS(ap_ideal, [0, 16]) *).
Proof.
 intros h0.
 assert (h1 := l50 h0).
 assert (h2 := l51 h0).
 apply t32. exact h1. exact h2.
Qed.
Lemma t33 : p48 -> p47.
Proof.
 intros h0.
 refine (float_absolute_wide_ne _ _ _ap_ideal i25 i24 h0 _) ; finalize.
Qed.
Lemma l48 : s1 -> p47 (* BND(ap - ap_ideal, [-8.88178e-16, 8.88178e-16]) *).
Proof.
 intros h0.
 assert (h1 := l49 h0).
 apply t33. exact h1.
Qed.
Definition f42 := Float2 (-1) (-52).
Definition f43 := Float2 (1) (-52).
Definition i29 := makepairF f42 f43.
Notation p53 := (BND r69 i29). (* BND(bq - bq_ideal, [-2.22045e-16, 2.22045e-16]) *)
Definition f44 := Float2 (1) (2).
Definition i30 := makepairF f9 f44.
Notation p54 := (ABS _bq_ideal i30). (* ABS(bq_ideal, [0, 4]) *)
Definition f45 := Float2 (1) (1).
Definition i31 := makepairF f41 f45.
Notation p55 := (ABS _beta i31). (* ABS(beta, [1, 2]) *)
Definition f46 := Float2 (-1) (1).
Definition i32 := makepairF f46 f20.
Notation p56 := (BND _beta i32). (* BND(beta, [-2, -1]) *)
Lemma t34 : p56 -> p55.
Proof.
 intros h0.
 refine (abs_of_bnd_n _beta i32 i31 h0 _) ; finalize.
Qed.
Lemma l54 : s1 -> p55 (* ABS(beta, [1, 2]) *).
Proof.
 intros h0.
 assert (h1 := l26 h0).
 apply t34. refine (subset _beta i13 i32 h1 _) ; finalize.
Qed.
Definition i33 := makepairF f9 f45.
Notation p57 := (ABS _q i33). (* ABS(q, [0, 2]) *)
Definition i34 := makepairF f46 f45.
Notation p58 := (BND _q i34). (* BND(q, [-2, 2]) *)
Lemma t35 : p58 -> p57.
Proof.
 intros h0.
 refine (abs_of_bnd_o _q i34 i33 h0 _) ; finalize.
Qed.
Lemma l55 : s1 -> p57 (* ABS(q, [0, 2]) *).
Proof.
 intros h0.
 assert (h1 := l21 h0).
 apply t35. refine (subset _q i2 i34 h1 _) ; finalize.
Qed.
Lemma t36 : p55 -> p57 -> p54.
Proof.
 intros h0 h1.
 refine (mul_aa _beta _q i31 i33 i30 h0 h1 _) ; finalize.
Qed.
Lemma l53 : s1 -> p54 (* ABS(bq_ideal, [0, 4]) *).
Proof.
 intros h0.
 assert (h1 := l54 h0).
 assert (h2 := l55 h0).
 apply t36. exact h1. exact h2.
Qed.
Lemma t37 : p54 -> p53.
Proof.
 intros h0.
 refine (float_absolute_wide_ne _ _ _bq_ideal i30 i29 h0 _) ; finalize.
Qed.
Lemma l52 : s1 -> p53 (* BND(bq - bq_ideal, [-2.22045e-16, 2.22045e-16]) *).
Proof.
 intros h0.
 assert (h1 := l53 h0).
 apply t37. exact h1.
Qed.
Lemma t38 : p47 -> p53 -> p46.
Proof.
 intros h0 h1.
 refine (add r68 r69 i24 i29 i27 h0 h1 _) ; finalize.
Qed.
Lemma l47 : s1 -> p46 (* BND(ap - ap_ideal + (bq - bq_ideal), [-1.11022e-15, 1.11022e-15]) *).
Proof.
 intros h0.
 assert (h1 := l48 h0).
 assert (h2 := l52 h0).
 apply t38. exact h1. exact h2.
Qed.
Lemma t39 : p46 -> p45.
Proof.
 intros h0.
 refine (add_mibs _ _ _ _ i27 h0) ; finalize.
Qed.
Lemma l46 : s1 -> p45 (* BND(ap + bq - p1_ideal, [-1.11022e-15, 1.11022e-15]) *).
Proof.
 intros h0.
 assert (h1 := l47 h0).
 apply t39. exact h1.
Qed.
Lemma t40 : p42 -> p45 -> p41.
Proof.
 intros h0 h1.
 refine (add r65 r66 i24 i27 i23 h0 h1 _) ; finalize.
Qed.
Lemma l43 : s1 -> p41 (* BND(p1 - (ap + bq) + (ap + bq - p1_ideal), [-1.9984e-15, 1.9984e-15]) *).
Proof.
 intros h0.
 assert (h1 := l44 h0).
 assert (h2 := l46 h0).
 apply t40. exact h1. exact h2.
Qed.
Lemma t41 : p41 -> p40.
Proof.
 intros h0.
 refine (sub_xals _ _ _ i23 h0) ; finalize.
Qed.
Lemma l42 : s1 -> p40 (* BND(p1 - p1_ideal, [-1.9984e-15, 1.9984e-15]) *).
Proof.
 intros h0.
 assert (h1 := l43 h0).
 apply t41. exact h1.
Qed.
Definition f47 := Float2 (-301924057609202447) (-107).
Definition f48 := Float2 (301924057609202447) (-107).
Definition i35 := makepairF f47 f48.
Notation p59 := (BND r26 i35). (* BND(p1_ideal - p_exact, [-1.86075e-15, 1.86075e-15]) *)
Notation p60 := (BND r45 i35). (* BND(-607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576 * p + 570419849984716187108541389157035433662294559263261888455660546024551170261 / 2301089569893738191214049136294392848876640076138894889705378020928991397008229047222665216 * q, [-1.86075e-15, 1.86075e-15]) *)
Definition f49 := Float2 (-113253297705605523) (-106).
Definition f50 := Float2 (113253297705605523) (-106).
Definition i36 := makepairF f49 f50.
Notation p61 := (BND r46 i36). (* BND(-607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576 * p, [-1.39595e-15, 1.39595e-15]) *)
Definition f51 := Float2 (-325762294523988919) (-111).
Definition f52 := Float2 (-1) (-53).
Definition i37 := makepairF f51 f52.
Notation p62 := (BND r47 i37). (* BND(-607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576, [-1.25479e-16, -1.11022e-16]) *)
Definition f53 := Float2 (-981305814791645417) (89).
Definition f54 := Float2 (-13) (145).
Definition i38 := makepairF f53 f54.
Notation p63 := (BND r48 i38). (* BND(-607398879457070813777175880614497980136962913, [-6.07399e+44, -5.79819e+44]) *)
Lemma t42 : p63.
Proof.
 refine (constant1 _ i38 _) ; finalize.
Qed.
Lemma l60 : s1 -> p63 (* BND(-607398879457070813777175880614497980136962913, [-6.07399e+44, -5.79819e+44]) *).
Proof.
 intros h0.
 apply t42.
Qed.
Definition f55 := Float2 (868247028191378451) (142).
Definition f56 := Float2 (13) (198).
Definition i39 := makepairF f55 f56.
Notation p64 := (BND r18 i39). (* BND(4840638936269341396294642382423593871270175513277109765144576, [4.84064e+60, 5.22255e+60]) *)
Lemma t43 : p64.
Proof.
 refine (constant1 _ i39 _) ; finalize.
Qed.
Lemma l61 : s1 -> p64 (* BND(4840638936269341396294642382423593871270175513277109765144576, [4.84064e+60, 5.22255e+60]) *).
Proof.
 intros h0.
 apply t43.
Qed.
Lemma t44 : p63 -> p64 -> p62.
Proof.
 intros h0 h1.
 refine (div_np r48 r18 i38 i39 i37 h0 h1 _) ; finalize.
Qed.
Lemma l59 : s1 -> p62 (* BND(-607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576, [-1.25479e-16, -1.11022e-16]) *).
Proof.
 intros h0.
 assert (h1 := l60 h0).
 assert (h2 := l61 h0).
 apply t44. exact h1. exact h2.
Qed.
Definition f57 := Float2 (-40720286815498615) (-108).
Definition i40 := makepairF f57 f52.
Notation p65 := (BND r47 i40). (* BND(-607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576, [-1.25479e-16, -1.11022e-16]) *)
Lemma t45 : p65 -> p1 -> p61.
Proof.
 intros h0 h1.
 refine (mul_no r47 _p i40 i1 i36 h0 h1 _) ; finalize.
Qed.
Lemma l58 : s1 -> p61 (* BND(-607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576 * p, [-1.39595e-15, 1.39595e-15]) *).
Proof.
 intros h0.
 assert (h1 := l59 h0).
 assert (h2 := l15 h0).
 apply t45. refine (subset r47 i37 i40 h1 _) ; finalize. exact h2.
Qed.
Definition f58 := Float2 (-75417462197991401) (-107).
Definition f59 := Float2 (75417462197991401) (-107).
Definition i41 := makepairF f58 f59.
Notation p66 := (BND r49 i41). (* BND(570419849984716187108541389157035433662294559263261888455660546024551170261 / 2301089569893738191214049136294392848876640076138894889705378020928991397008229047222665216 * q, [-4.64796e-16, 4.64796e-16]) *)
Definition f60 := Float2 (643562344089526621) (-111).
Definition i42 := makepairF f43 f60.
Notation p67 := (BND r50 i42). (* BND(570419849984716187108541389157035433662294559263261888455660546024551170261 / 2301089569893738191214049136294392848876640076138894889705378020928991397008229047222665216, [2.22045e-16, 2.47891e-16]) *)
Definition f61 := Float2 (5) (246).
Definition f62 := Float2 (5679570306000239) (196).
Definition i43 := makepairF f61 f62.
Notation p68 := (BND r51 i43). (* BND(570419849984716187108541389157035433662294559263261888455660546024551170261, [5.65391e+74, 5.7042e+74]) *)
Lemma t46 : p68.
Proof.
 refine (constant1 _ i43 _) ; finalize.
Qed.
Lemma l64 : s1 -> p68 (* BND(570419849984716187108541389157035433662294559263261888455660546024551170261, [5.65391e+74, 5.7042e+74]) *).
Proof.
 intros h0.
 apply t46.
Qed.
Definition f63 := Float2 (325592635571766919) (242).
Definition f64 := Float2 (5) (298).
Definition i44 := makepairF f63 f64.
Notation p69 := (BND r22 i44). (* BND(2301089569893738191214049136294392848876640076138894889705378020928991397008229047222665216, [2.30109e+90, 2.54629e+90]) *)
Lemma t47 : p69.
Proof.
 refine (constant1 _ i44 _) ; finalize.
Qed.
Lemma l65 : s1 -> p69 (* BND(2301089569893738191214049136294392848876640076138894889705378020928991397008229047222665216, [2.30109e+90, 2.54629e+90]) *).
Proof.
 intros h0.
 apply t47.
Qed.
Lemma t48 : p68 -> p69 -> p67.
Proof.
 intros h0 h1.
 refine (div_pp r51 r22 i43 i44 i42 h0 h1 _) ; finalize.
Qed.
Lemma l63 : s1 -> p67 (* BND(570419849984716187108541389157035433662294559263261888455660546024551170261 / 2301089569893738191214049136294392848876640076138894889705378020928991397008229047222665216, [2.22045e-16, 2.47891e-16]) *).
Proof.
 intros h0.
 assert (h1 := l64 h0).
 assert (h2 := l65 h0).
 apply t48. exact h1. exact h2.
Qed.
Lemma t49 : p67 -> p2 -> p66.
Proof.
 intros h0 h1.
 refine (mul_po r50 _q i42 i2 i41 h0 h1 _) ; finalize.
Qed.
Lemma l62 : s1 -> p66 (* BND(570419849984716187108541389157035433662294559263261888455660546024551170261 / 2301089569893738191214049136294392848876640076138894889705378020928991397008229047222665216 * q, [-4.64796e-16, 4.64796e-16]) *).
Proof.
 intros h0.
 assert (h1 := l63 h0).
 assert (h2 := l21 h0).
 apply t49. exact h1. exact h2.
Qed.
Lemma t50 : p61 -> p66 -> p60.
Proof.
 intros h0 h1.
 refine (add r46 r49 i36 i41 i35 h0 h1 _) ; finalize.
Qed.
Lemma l57 : s1 -> p60 (* BND(-607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576 * p + 570419849984716187108541389157035433662294559263261888455660546024551170261 / 2301089569893738191214049136294392848876640076138894889705378020928991397008229047222665216 * q, [-1.86075e-15, 1.86075e-15]) *).
Proof.
 intros h0.
 assert (h1 := l58 h0).
 assert (h2 := l62 h0).
 apply t50. exact h1. exact h2.
Qed.
Definition i45 := makepairF f9 f9.
Notation p70 := (REL r26 r45 i45). (* REL(p1_ideal - p_exact, -607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576 * p + 570419849984716187108541389157035433662294559263261888455660546024551170261 / 2301089569893738191214049136294392848876640076138894889705378020928991397008229047222665216 * q, [0, 0]) *)
Notation p71 := (r26 = r45). (* EQL(p1_ideal - p_exact, -607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576 * p + 570419849984716187108541389157035433662294559263261888455660546024551170261 / 2301089569893738191214049136294392848876640076138894889705378020928991397008229047222665216 * q) *)
Lemma t51 : p71.
Proof.
 refine (b3) ; finalize.
Qed.
Lemma l67 : s1 -> p71 (* EQL(p1_ideal - p_exact, -607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576 * p + 570419849984716187108541389157035433662294559263261888455660546024551170261 / 2301089569893738191214049136294392848876640076138894889705378020928991397008229047222665216 * q) *).
Proof.
 intros h0.
 apply t51.
Qed.
Notation p72 := (REL r45 r45 i45). (* REL(-607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576 * p + 570419849984716187108541389157035433662294559263261888455660546024551170261 / 2301089569893738191214049136294392848876640076138894889705378020928991397008229047222665216 * q, -607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576 * p + 570419849984716187108541389157035433662294559263261888455660546024551170261 / 2301089569893738191214049136294392848876640076138894889705378020928991397008229047222665216 * q, [0, 0]) *)
Lemma t52 : p72.
Proof.
 refine (rel_refl r45 i45 _) ; finalize.
Qed.
Lemma l68 : s1 -> p72 (* REL(-607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576 * p + 570419849984716187108541389157035433662294559263261888455660546024551170261 / 2301089569893738191214049136294392848876640076138894889705378020928991397008229047222665216 * q, -607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576 * p + 570419849984716187108541389157035433662294559263261888455660546024551170261 / 2301089569893738191214049136294392848876640076138894889705378020928991397008229047222665216 * q, [0, 0]) *).
Proof.
 intros h0.
 apply t52.
Qed.
Lemma t53 : p71 -> p72 -> p70.
Proof.
 intros h0 h1.
 refine (rel_rewrite_1 r26 r45 r45 i45 h0 h1) ; finalize.
Qed.
Lemma l66 : s1 -> p70 (* REL(p1_ideal - p_exact, -607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576 * p + 570419849984716187108541389157035433662294559263261888455660546024551170261 / 2301089569893738191214049136294392848876640076138894889705378020928991397008229047222665216 * q, [0, 0]) *).
Proof.
 intros h0.
 assert (h1 := l67 h0).
 assert (h2 := l68 h0).
 apply t53. exact h1. exact h2.
Qed.
Lemma t54 : p60 -> p70 -> p59.
Proof.
 intros h0 h1.
 refine (bnd_of_bnd_rel_o r26 r45 i35 i45 i35 h0 h1 _) ; finalize.
Qed.
Lemma l56 : s1 -> p59 (* BND(p1_ideal - p_exact, [-1.86075e-15, 1.86075e-15]) *).
Proof.
 intros h0.
 assert (h1 := l57 h0).
 assert (h2 := l66 h0).
 apply t54. exact h1. exact h2.
Qed.
Lemma t55 : p40 -> p59 -> p39.
Proof.
 intros h0 h1.
 refine (add r24 r26 i23 i35 i3 h0 h1 _) ; finalize.
Qed.
Lemma l41 : s1 -> p39 (* BND(p1 - p1_ideal + (p1_ideal - p_exact), [-3.85915e-15, 3.85915e-15]) *).
Proof.
 intros h0.
 assert (h1 := l42 h0).
 assert (h2 := l56 h0).
 apply t55. exact h1. exact h2.
Qed.
Notation p73 := (REL r1 r23 i45). (* REL(p1 - p_exact, p1 - p1_ideal + (p1_ideal - p_exact), [0, 0]) *)
Notation p74 := (r1 = r23). (* EQL(p1 - p_exact, p1 - p1_ideal + (p1_ideal - p_exact)) *)
Lemma t56 : p74.
Proof.
 refine (b1) ; finalize.
Qed.
Lemma l70 : s1 -> p74 (* EQL(p1 - p_exact, p1 - p1_ideal + (p1_ideal - p_exact)) *).
Proof.
 intros h0.
 apply t56.
Qed.
Notation p75 := (REL r23 r23 i45). (* REL(p1 - p1_ideal + (p1_ideal - p_exact), p1 - p1_ideal + (p1_ideal - p_exact), [0, 0]) *)
Lemma t57 : p75.
Proof.
 refine (rel_refl r23 i45 _) ; finalize.
Qed.
Lemma l71 : s1 -> p75 (* REL(p1 - p1_ideal + (p1_ideal - p_exact), p1 - p1_ideal + (p1_ideal - p_exact), [0, 0]) *).
Proof.
 intros h0.
 apply t57.
Qed.
Lemma t58 : p74 -> p75 -> p73.
Proof.
 intros h0 h1.
 refine (rel_rewrite_1 r1 r23 r23 i45 h0 h1) ; finalize.
Qed.
Lemma l69 : s1 -> p73 (* REL(p1 - p_exact, p1 - p1_ideal + (p1_ideal - p_exact), [0, 0]) *).
Proof.
 intros h0.
 assert (h1 := l70 h0).
 assert (h2 := l71 h0).
 apply t58. exact h1. exact h2.
Qed.
Lemma t59 : p39 -> p73 -> p3.
Proof.
 intros h0 h1.
 refine (bnd_of_bnd_rel_o r1 r23 i3 i45 i3 h0 h1 _) ; finalize.
Qed.
Lemma l40 : s1 -> p3 (* BND(p1 - p_exact, [-3.85915e-15, 3.85915e-15]) *).
Proof.
 intros h0.
 assert (h1 := l41 h0).
 assert (h2 := l69 h0).
 apply t59. exact h1. exact h2.
Qed.
Lemma l2 : s1 -> s11.
Proof.
 intros h0.
 assert (h1 := l3 h0).
 assert (h2 := l40 h0).
 refine (simplify (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 1%nat i4)) (Abnd 0%nat i3) (List.cons r1 (List.cons r27 List.nil)) h2 h1 _) ; finalize.
Qed.
Notation p76 := (BND r41 i4). (* BND(q1 - q1_ideal + (q1_ideal - q_exact), [-6.98336e-16, 6.98336e-16]) *)
Definition f65 := Float2 (-7) (-54).
Definition f66 := Float2 (7) (-54).
Definition i46 := makepairF f65 f66.
Notation p77 := (BND r42 i46). (* BND(q1 - q1_ideal, [-3.88578e-16, 3.88578e-16]) *)
Notation r71 := ((_q1 - r29)%R).
Notation r72 := ((r29 - _q1_ideal)%R).
Notation r70 := ((r71 + r72)%R).
Notation p78 := (BND r70 i46). (* BND(q1 - (gp + dq) + (gp + dq - q1_ideal), [-3.88578e-16, 3.88578e-16]) *)
Notation p79 := (BND r71 i29). (* BND(q1 - (gp + dq), [-2.22045e-16, 2.22045e-16]) *)
Notation p80 := (ABS r29 i30). (* ABS(gp + dq, [0, 4]) *)
Definition f67 := Float2 (-1) (2).
Definition i47 := makepairF f67 f44.
Notation p81 := (BND r29 i47). (* BND(gp + dq, [-4, 4]) *)
Lemma t60 : p81 -> p80.
Proof.
 intros h0.
 refine (abs_of_bnd_o r29 i47 i30 h0 _) ; finalize.
Qed.
Lemma l77 : s1 -> p80 (* ABS(gp + dq, [0, 4]) *).
Proof.
 intros h0.
 assert (h1 := l39 h0).
 apply t60. refine (subset r29 i21 i47 h1 _) ; finalize.
Qed.
Lemma t61 : p80 -> p79.
Proof.
 intros h0.
 refine (float_absolute_wide_ne _ _ r29 i30 i29 h0 _) ; finalize.
Qed.
Lemma l76 : s1 -> p79 (* BND(q1 - (gp + dq), [-2.22045e-16, 2.22045e-16]) *).
Proof.
 intros h0.
 assert (h1 := l77 h0).
 apply t61. exact h1.
Qed.
Definition f68 := Float2 (-3) (-54).
Definition f69 := Float2 (3) (-54).
Definition i48 := makepairF f68 f69.
Notation p82 := (BND r72 i48). (* BND(gp + dq - q1_ideal, [-1.66533e-16, 1.66533e-16]) *)
Notation r74 := ((_gp - _gp_ideal)%R).
Notation r75 := ((_dq - _dq_ideal)%R).
Notation r73 := ((r74 + r75)%R).
Notation p83 := (BND r73 i48). (* BND(gp - gp_ideal + (dq - dq_ideal), [-1.66533e-16, 1.66533e-16]) *)
Definition f70 := Float2 (-1) (-54).
Definition f71 := Float2 (1) (-54).
Definition i49 := makepairF f70 f71.
Notation p84 := (BND r74 i49). (* BND(gp - gp_ideal, [-5.55112e-17, 5.55112e-17]) *)
Definition i50 := makepairF f9 f41.
Notation p85 := (ABS _gp_ideal i50). (* ABS(gp_ideal, [0, 1]) *)
Definition f72 := Float2 (1) (-4).
Definition i51 := makepairF f23 f72.
Notation p86 := (ABS _gamma i51). (* ABS(gamma, [0.03125, 0.0625]) *)
Notation p87 := (BND _gamma i51). (* BND(gamma, [0.03125, 0.0625]) *)
Lemma t62 : p87 -> p86.
Proof.
 intros h0.
 refine (abs_of_bnd_p _gamma i51 i51 h0 _) ; finalize.
Qed.
Lemma l82 : s1 -> p86 (* ABS(gamma, [0.03125, 0.0625]) *).
Proof.
 intros h0.
 assert (h1 := l31 h0).
 apply t62. refine (subset _gamma i16 i51 h1 _) ; finalize.
Qed.
Lemma t63 : p86 -> p51 -> p85.
Proof.
 intros h0 h1.
 refine (mul_aa _gamma _p i51 i25 i50 h0 h1 _) ; finalize.
Qed.
Lemma l81 : s1 -> p85 (* ABS(gp_ideal, [0, 1]) *).
Proof.
 intros h0.
 assert (h1 := l82 h0).
 assert (h2 := l51 h0).
 apply t63. exact h1. exact h2.
Qed.
Lemma t64 : p85 -> p84.
Proof.
 intros h0.
 refine (float_absolute_wide_ne _ _ _gp_ideal i50 i49 h0 _) ; finalize.
Qed.
Lemma l80 : s1 -> p84 (* BND(gp - gp_ideal, [-5.55112e-17, 5.55112e-17]) *).
Proof.
 intros h0.
 assert (h1 := l81 h0).
 apply t64. exact h1.
Qed.
Definition f73 := Float2 (1) (-53).
Definition i52 := makepairF f52 f73.
Notation p88 := (BND r75 i52). (* BND(dq - dq_ideal, [-1.11022e-16, 1.11022e-16]) *)
Notation p89 := (ABS _dq_ideal i33). (* ABS(dq_ideal, [0, 2]) *)
Lemma t65 : p49 -> p57 -> p89.
Proof.
 intros h0 h1.
 refine (mul_aa _delta _q i28 i33 i33 h0 h1 _) ; finalize.
Qed.
Lemma l84 : s1 -> p89 (* ABS(dq_ideal, [0, 2]) *).
Proof.
 intros h0.
 assert (h1 := l50 h0).
 assert (h2 := l55 h0).
 apply t65. exact h1. exact h2.
Qed.
Lemma t66 : p89 -> p88.
Proof.
 intros h0.
 refine (float_absolute_wide_ne _ _ _dq_ideal i33 i52 h0 _) ; finalize.
Qed.
Lemma l83 : s1 -> p88 (* BND(dq - dq_ideal, [-1.11022e-16, 1.11022e-16]) *).
Proof.
 intros h0.
 assert (h1 := l84 h0).
 apply t66. exact h1.
Qed.
Lemma t67 : p84 -> p88 -> p83.
Proof.
 intros h0 h1.
 refine (add r74 r75 i49 i52 i48 h0 h1 _) ; finalize.
Qed.
Lemma l79 : s1 -> p83 (* BND(gp - gp_ideal + (dq - dq_ideal), [-1.66533e-16, 1.66533e-16]) *).
Proof.
 intros h0.
 assert (h1 := l80 h0).
 assert (h2 := l83 h0).
 apply t67. exact h1. exact h2.
Qed.
Lemma t68 : p83 -> p82.
Proof.
 intros h0.
 refine (add_mibs _ _ _ _ i48 h0) ; finalize.
Qed.
Lemma l78 : s1 -> p82 (* BND(gp + dq - q1_ideal, [-1.66533e-16, 1.66533e-16]) *).
Proof.
 intros h0.
 assert (h1 := l79 h0).
 apply t68. exact h1.
Qed.
Lemma t69 : p79 -> p82 -> p78.
Proof.
 intros h0 h1.
 refine (add r71 r72 i29 i48 i46 h0 h1 _) ; finalize.
Qed.
Lemma l75 : s1 -> p78 (* BND(q1 - (gp + dq) + (gp + dq - q1_ideal), [-3.88578e-16, 3.88578e-16]) *).
Proof.
 intros h0.
 assert (h1 := l76 h0).
 assert (h2 := l78 h0).
 apply t69. exact h1. exact h2.
Qed.
Lemma t70 : p78 -> p77.
Proof.
 intros h0.
 refine (sub_xals _ _ _ i46 h0) ; finalize.
Qed.
Lemma l74 : s1 -> p77 (* BND(q1 - q1_ideal, [-3.88578e-16, 3.88578e-16]) *).
Proof.
 intros h0.
 assert (h1 := l75 h0).
 apply t70. exact h1.
Qed.
Definition f74 := Float2 (-402088739940410689) (-110).
Definition f75 := Float2 (402088739940410689) (-110).
Definition i53 := makepairF f74 f75.
Notation p90 := (BND r44 i53). (* BND(q1_ideal - q_exact, [-3.09758e-16, 3.09758e-16]) *)
Notation p91 := (BND r52 i53). (* BND(-36845085767445699368127421840329 / 5503169332165886540104386747797882289057924382720 * p + -607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576 * q, [-3.09758e-16, 3.09758e-16]) *)
Definition f76 := Float2 (-96686588824171077) (-110).
Definition f77 := Float2 (96686588824171077) (-110).
Definition i54 := makepairF f76 f77.
Notation p92 := (BND r53 i54). (* BND(-36845085767445699368127421840329 / 5503169332165886540104386747797882289057924382720 * p, [-7.44846e-17, 7.44846e-17]) *)
Definition f78 := Float2 (-278109738640312311) (-115).
Definition f79 := Float2 (-1) (-58).
Definition i55 := makepairF f78 f79.
Notation p93 := (BND r54 i55). (* BND(-36845085767445699368127421840329 / 5503169332165886540104386747797882289057924382720, [-6.69525e-18, -3.46945e-18]) *)
Definition f80 := Float2 (-523600160810327955) (46).
Definition f81 := Float2 (-1) (104).
Definition i56 := makepairF f80 f81.
Notation p94 := (BND r55 i56). (* BND(-36845085767445699368127421840329, [-3.68451e+31, -2.02824e+31]) *)
Lemma t71 : p94.
Proof.
 refine (constant1 _ i56 _) ; finalize.
Qed.
Lemma l89 : s1 -> p94 (* BND(-36845085767445699368127421840329, [-3.68451e+31, -2.02824e+31]) *).
Proof.
 intros h0.
 apply t71.
Qed.
Definition f82 := Float2 (542654392619611531) (103).
Definition f83 := Float2 (1) (162).
Definition i57 := makepairF f82 f83.
Notation p95 := (BND r56 i57). (* BND(5503169332165886540104386747797882289057924382720, [5.50317e+48, 5.84601e+48]) *)
Lemma t72 : p95.
Proof.
 refine (constant1 _ i57 _) ; finalize.
Qed.
Lemma l90 : s1 -> p95 (* BND(5503169332165886540104386747797882289057924382720, [5.50317e+48, 5.84601e+48]) *).
Proof.
 intros h0.
 apply t72.
Qed.
Lemma t73 : p94 -> p95 -> p93.
Proof.
 intros h0 h1.
 refine (div_np r55 r56 i56 i57 i55 h0 h1 _) ; finalize.
Qed.
Lemma l88 : s1 -> p93 (* BND(-36845085767445699368127421840329 / 5503169332165886540104386747797882289057924382720, [-6.69525e-18, -3.46945e-18]) *).
Proof.
 intros h0.
 assert (h1 := l89 h0).
 assert (h2 := l90 h0).
 apply t73. exact h1. exact h2.
Qed.
Lemma t74 : p93 -> p1 -> p92.
Proof.
 intros h0 h1.
 refine (mul_no r54 _p i55 i1 i54 h0 h1 _) ; finalize.
Qed.
Lemma l87 : s1 -> p92 (* BND(-36845085767445699368127421840329 / 5503169332165886540104386747797882289057924382720 * p, [-7.44846e-17, 7.44846e-17]) *).
Proof.
 intros h0.
 assert (h1 := l88 h0).
 assert (h2 := l15 h0).
 apply t74. exact h1. exact h2.
Qed.
Definition f84 := Float2 (-76350537779059903) (-108).
Definition f85 := Float2 (76350537779059903) (-108).
Definition i58 := makepairF f84 f85.
Notation p96 := (BND r57 i58). (* BND(-607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576 * q, [-2.35273e-16, 2.35273e-16]) *)
Lemma t75 : p62 -> p2 -> p96.
Proof.
 intros h0 h1.
 refine (mul_no r47 _q i37 i2 i58 h0 h1 _) ; finalize.
Qed.
Lemma l91 : s1 -> p96 (* BND(-607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576 * q, [-2.35273e-16, 2.35273e-16]) *).
Proof.
 intros h0.
 assert (h1 := l59 h0).
 assert (h2 := l21 h0).
 apply t75. exact h1. exact h2.
Qed.
Lemma t76 : p92 -> p96 -> p91.
Proof.
 intros h0 h1.
 refine (add r53 r57 i54 i58 i53 h0 h1 _) ; finalize.
Qed.
Lemma l86 : s1 -> p91 (* BND(-36845085767445699368127421840329 / 5503169332165886540104386747797882289057924382720 * p + -607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576 * q, [-3.09758e-16, 3.09758e-16]) *).
Proof.
 intros h0.
 assert (h1 := l87 h0).
 assert (h2 := l91 h0).
 apply t76. exact h1. exact h2.
Qed.
Notation p97 := (REL r44 r52 i45). (* REL(q1_ideal - q_exact, -36845085767445699368127421840329 / 5503169332165886540104386747797882289057924382720 * p + -607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576 * q, [0, 0]) *)
Notation p98 := (r44 = r52). (* EQL(q1_ideal - q_exact, -36845085767445699368127421840329 / 5503169332165886540104386747797882289057924382720 * p + -607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576 * q) *)
Lemma t77 : p98.
Proof.
 refine (b4) ; finalize.
Qed.
Lemma l93 : s1 -> p98 (* EQL(q1_ideal - q_exact, -36845085767445699368127421840329 / 5503169332165886540104386747797882289057924382720 * p + -607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576 * q) *).
Proof.
 intros h0.
 apply t77.
Qed.
Notation p99 := (REL r52 r52 i45). (* REL(-36845085767445699368127421840329 / 5503169332165886540104386747797882289057924382720 * p + -607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576 * q, -36845085767445699368127421840329 / 5503169332165886540104386747797882289057924382720 * p + -607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576 * q, [0, 0]) *)
Lemma t78 : p99.
Proof.
 refine (rel_refl r52 i45 _) ; finalize.
Qed.
Lemma l94 : s1 -> p99 (* REL(-36845085767445699368127421840329 / 5503169332165886540104386747797882289057924382720 * p + -607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576 * q, -36845085767445699368127421840329 / 5503169332165886540104386747797882289057924382720 * p + -607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576 * q, [0, 0]) *).
Proof.
 intros h0.
 apply t78.
Qed.
Lemma t79 : p98 -> p99 -> p97.
Proof.
 intros h0 h1.
 refine (rel_rewrite_1 r44 r52 r52 i45 h0 h1) ; finalize.
Qed.
Lemma l92 : s1 -> p97 (* REL(q1_ideal - q_exact, -36845085767445699368127421840329 / 5503169332165886540104386747797882289057924382720 * p + -607398879457070813777175880614497980136962913 / 4840638936269341396294642382423593871270175513277109765144576 * q, [0, 0]) *).
Proof.
 intros h0.
 assert (h1 := l93 h0).
 assert (h2 := l94 h0).
 apply t79. exact h1. exact h2.
Qed.
Lemma t80 : p91 -> p97 -> p90.
Proof.
 intros h0 h1.
 refine (bnd_of_bnd_rel_o r44 r52 i53 i45 i53 h0 h1 _) ; finalize.
Qed.
Lemma l85 : s1 -> p90 (* BND(q1_ideal - q_exact, [-3.09758e-16, 3.09758e-16]) *).
Proof.
 intros h0.
 assert (h1 := l86 h0).
 assert (h2 := l92 h0).
 apply t80. exact h1. exact h2.
Qed.
Lemma t81 : p77 -> p90 -> p76.
Proof.
 intros h0 h1.
 refine (add r42 r44 i46 i53 i4 h0 h1 _) ; finalize.
Qed.
Lemma l73 : s1 -> p76 (* BND(q1 - q1_ideal + (q1_ideal - q_exact), [-6.98336e-16, 6.98336e-16]) *).
Proof.
 intros h0.
 assert (h1 := l74 h0).
 assert (h2 := l85 h0).
 apply t81. exact h1. exact h2.
Qed.
Notation p100 := (REL r27 r41 i45). (* REL(q1 - q_exact, q1 - q1_ideal + (q1_ideal - q_exact), [0, 0]) *)
Notation p101 := (r27 = r41). (* EQL(q1 - q_exact, q1 - q1_ideal + (q1_ideal - q_exact)) *)
Lemma t82 : p101.
Proof.
 refine (b2) ; finalize.
Qed.
Lemma l96 : s1 -> p101 (* EQL(q1 - q_exact, q1 - q1_ideal + (q1_ideal - q_exact)) *).
Proof.
 intros h0.
 apply t82.
Qed.
Notation p102 := (REL r41 r41 i45). (* REL(q1 - q1_ideal + (q1_ideal - q_exact), q1 - q1_ideal + (q1_ideal - q_exact), [0, 0]) *)
Lemma t83 : p102.
Proof.
 refine (rel_refl r41 i45 _) ; finalize.
Qed.
Lemma l97 : s1 -> p102 (* REL(q1 - q1_ideal + (q1_ideal - q_exact), q1 - q1_ideal + (q1_ideal - q_exact), [0, 0]) *).
Proof.
 intros h0.
 apply t83.
Qed.
Lemma t84 : p101 -> p102 -> p100.
Proof.
 intros h0 h1.
 refine (rel_rewrite_1 r27 r41 r41 i45 h0 h1) ; finalize.
Qed.
Lemma l95 : s1 -> p100 (* REL(q1 - q_exact, q1 - q1_ideal + (q1_ideal - q_exact), [0, 0]) *).
Proof.
 intros h0.
 assert (h1 := l96 h0).
 assert (h2 := l97 h0).
 apply t84. exact h1. exact h2.
Qed.
Lemma t85 : p76 -> p100 -> p4.
Proof.
 intros h0 h1.
 refine (bnd_of_bnd_rel_o r27 r41 i4 i45 i4 h0 h1 _) ; finalize.
Qed.
Lemma l72 : s1 -> p4 (* BND(q1 - q_exact, [-6.98336e-16, 6.98336e-16]) *).
Proof.
 intros h0.
 assert (h1 := l73 h0).
 assert (h2 := l95 h0).
 apply t85. exact h1. exact h2.
Qed.
Lemma l1 : s1 -> False.
Proof.
 intros h0.
 assert (h1 := l2 h0).
 assert (h2 := l72 h0).
 refine (simplify (Tatom false (Abnd 0%nat i4)) Tfalse (Abnd 0%nat i4) (List.cons r27 List.nil) h2 h1 _) ; finalize.
Qed.
End Generated_by_Gappa.
End Gappa_N20.

Module Lifting_N20.
(* The lifting lemma of phi3-matrix in double (simpson-verify, issue 29): Phi, the invariant form Q and the one-step
   bound (Bp, Bq) are the harness's, exactly; Bp and Bq are Gappa's bound, proved in its own certificate.
   The float iterate is y_(k+1) = Phi y_k + e_k with |e_k| <= (Bp, Bq) while y_k stays in the box; the error
   d_k = y_k - Phi^k y_0 then obeys d_(k+1) = Phi d_k + e_k, and sqrt(Q(d_n)) <= n eps. *)
Open Scope R_scope.

Definition a := (4603719609199889721500218209637141174193549725516937316940641 / 4840638936269341396294642382423593871270175513277109765144576).
Definition b := (-4467912064472210654272016230342243611753646281573833613883785510285988932817859942208192725 / 2301089569893738191214049136294392848876640076138894889705378020928991397008229047222665216).
Definition c := (7512069526796455666203966915693 / 152743632524540333131446066755540).
Definition d := (4603719609199889721500218209637141174193549725516937316940641 / 4840638936269341396294642382423593871270175513277109765144576).
Definition wp := (1 / 1).
Definition wq := (22339560322361053271360081151711218058768231407869168069418927551429944664089299711040963625 / 565848295955993203641464547239755794525421885770007114686624489826935414477582009039323136).
Definition Bp := (626183230779878159 / 162259276829213363391578010288128).
Definition Bq := (906491898205906241 / 1298074214633706907132624082305024).
Definition eps := (1851873232088765 / 316912650057057350374175801344).

Definition Q (x y : R) := wp * x * x + wq * y * y.

Lemma Q_nonneg : forall x y, 0 <= Q x y.
Proof. intros. unfold Q, wp, wq. nra. Qed.

Lemma invariant : forall x y, Q (a * x + b * y) (c * x + d * y) = Q x y.
Proof. intros. unfold Q, a, b, c, d, wp, wq. field. Qed.

Lemma one_step : forall ex ey, -Bp <= ex <= Bp -> -Bq <= ey <= Bq -> Q ex ey <= eps * eps.
Proof. intros ex ey Hx Hy. unfold Q, wp, wq, Bp, Bq, eps in *. nra. Qed.

Lemma cauchy : forall x1 y1 x2 y2, wp * x1 * x2 + wq * y1 * y2 <= sqrt (Q x1 y1) * sqrt (Q x2 y2).
Proof.
  intros. rewrite <- sqrt_mult by apply Q_nonneg.
  destruct (Rle_or_lt (wp * x1 * x2 + wq * y1 * y2) 0) as [H | H].
  - apply Rle_trans with 0; [exact H | apply sqrt_pos].
  - apply Rsqr_incr_0_var; [| apply sqrt_pos].
    rewrite Rsqr_sqrt by (apply Rmult_le_pos; apply Q_nonneg).
    assert (W : 0 <= wp * wq) by (unfold wp, wq; lra).
    pose proof (Rle_0_sqr (x1 * y2 - x2 * y1)) as Sq. unfold Rsqr in Sq.
    assert (0 <= wp * wq * ((x1 * y2 - x2 * y1) * (x1 * y2 - x2 * y1))) by (apply Rmult_le_pos; assumption).
    unfold Rsqr, Q. nra.
Qed.

Lemma triangle : forall x1 y1 x2 y2, sqrt (Q (x1 + x2) (y1 + y2)) <= sqrt (Q x1 y1) + sqrt (Q x2 y2).
Proof.
  intros. apply Rsqr_incr_0_var; [| apply Rplus_le_le_0_compat; apply sqrt_pos].
  rewrite Rsqr_sqrt by apply Q_nonneg.
  pose proof (cauchy x1 y1 x2 y2) as C.
  pose proof (sqrt_sqrt (Q x1 y1) (Q_nonneg x1 y1)) as S1.
  pose proof (sqrt_sqrt (Q x2 y2) (Q_nonneg x2 y2)) as S2.
  unfold Rsqr. unfold Q in *. nra.
Qed.

Theorem lifting : forall (dp dq ep eq : nat -> R),
  dp 0%nat = 0 -> dq 0%nat = 0 ->
  (forall k, dp (S k) = a * dp k + b * dq k + ep k) ->
  (forall k, dq (S k) = c * dp k + d * dq k + eq k) ->
  (forall k, -Bp <= ep k <= Bp /\ -Bq <= eq k <= Bq) ->
  forall n, sqrt (Q (dp n) (dq n)) <= INR n * eps.
Proof.
  intros dp dq ep eq H0p H0q Hp Hq He n. induction n as [| n IH].
  - rewrite H0p, H0q. unfold Q. simpl. replace (wp * 0 * 0 + wq * 0 * 0) with 0 by ring. rewrite sqrt_0. lra.
  - rewrite Hp, Hq, S_INR.
    eapply Rle_trans; [apply triangle |].
    rewrite invariant.
    assert (sqrt (Q (ep n) (eq n)) <= eps).
    { destruct (He n) as [Hx Hy].
      rewrite <- (sqrt_square eps) by (unfold eps; lra).
      apply sqrt_le_1_alt. apply one_step; assumption. }
    lra.
Qed.
End Lifting_N20.

Module Gappa_N40.
Section Generated_by_Gappa.
Notation _delta := (float2R (Float2 (8896305638502983) (-53))).
Variable _p_input : R.
Notation _p := ((rounding_float rndNE (53)%positive (-1074)%Z) _p_input).
Notation _ap_ideal := ((_delta * _p)%R).
Notation _ap := ((rounding_float rndNE (53)%positive (-1074)%Z) _ap_ideal).
Notation _beta := (float2R (Float2 (-553328001895381) (-49))).
Variable _q_input : R.
Notation _q := ((rounding_float rndNE (53)%positive (-1074)%Z) _q_input).
Notation _bq_ideal := ((_beta * _q)%R).
Notation _bq := ((rounding_float rndNE (53)%positive (-1074)%Z) _bq_ideal).
Notation r3 := ((_ap + _bq)%R).
Notation _p1 := ((rounding_float rndNE (53)%positive (-1074)%Z) r3).
Notation r17 := (Float1 (76261713085606223321819560886785958185474988892094483350567777)).
Notation r18 := (Float1 (77212325338401015504689204853976229175880009829288981131427840)).
Notation _delta_exact := ((r17 / r18)%R).
Notation r15 := ((_delta_exact * _p)%R).
Notation r21 := (Float1 (-14430797040402638931187821021425337574080128090175933931085415253899271220252790495036876433)).
Notation r22 := (Float1 (14681737584036205971792085335481670627880553447618287576963763260000045253935184688946610176)).
Notation _beta_exact := ((r21 / r22)%R).
Notation r19 := ((_beta_exact * _q)%R).
Notation _p_exact := ((r15 + r19)%R).
Notation r1 := ((_p1 - _p_exact)%R).
Notation _p1_ideal := ((_ap_ideal + _bq_ideal)%R).
Notation r24 := ((_p1 - _p1_ideal)%R).
Notation r26 := ((_p1_ideal - _p_exact)%R).
Notation r23 := ((r24 + r26)%R).
Lemma a1 : r1 = r23.
Proof. first [ring | unfold float2R, Float1, Defs.F2R; simpl; unfold Z.pow_pos; simpl; field]. Qed.
Lemma b1 : r1 = r23.
 apply a1.
Qed.
Notation _gamma := (float2R (Float2 (7176157339393379) (-58))).
Notation _gp_ideal := ((_gamma * _p)%R).
Notation _gp := ((rounding_float rndNE (53)%positive (-1074)%Z) _gp_ideal).
Notation _dq_ideal := ((_delta * _q)%R).
Notation _dq := ((rounding_float rndNE (53)%positive (-1074)%Z) _dq_ideal).
Notation r29 := ((_gp + _dq)%R).
Notation _q1 := ((rounding_float rndNE (53)%positive (-1074)%Z) r29).
Notation r38 := (Float1 (30329780330904584893144624612461)).
Notation r39 := (Float1 (1218195697213405835340518441381800)).
Notation _gamma_exact := ((r38 / r39)%R).
Notation r36 := ((_gamma_exact * _p)%R).
Notation r40 := ((_delta_exact * _q)%R).
Notation _q_exact := ((r36 + r40)%R).
Notation r27 := ((_q1 - _q_exact)%R).
Notation _q1_ideal := ((_gp_ideal + _dq_ideal)%R).
Notation r42 := ((_q1 - _q1_ideal)%R).
Notation r44 := ((_q1_ideal - _q_exact)%R).
Notation r41 := ((r42 + r44)%R).
Lemma a2 : r27 = r41.
Proof. first [ring | unfold float2R, Float1, Defs.F2R; simpl; unfold Z.pow_pos; simpl; field]. Qed.
Lemma b2 : r27 = r41.
 apply a2.
Qed.
Notation r48 := (Float1 (-3660383455318603984232747923630239280051403617)).
Notation r47 := ((r48 / r18)%R).
Notation r46 := ((r47 * _p)%R).
Notation r51 := (Float1 (725368870011116500311633037363284098815934157950200991855380254176979494545)).
Notation r50 := ((r51 / r22)%R).
Notation r49 := ((r50 * _q)%R).
Notation r45 := ((r46 + r49)%R).
Lemma a3 : r26 = r45.
Proof. first [ring | unfold float2R, Float1, Defs.F2R; simpl; unfold Z.pow_pos; simpl; field]. Qed.
Lemma b3 : r26 = r45.
 apply a3.
Qed.
Notation r55 := (Float1 (-6671878411859531223066906417473)).
Notation r56 := (Float1 (43890125504277088739791682231712132520374330982400)).
Notation r54 := ((r55 / r56)%R).
Notation r53 := ((r54 * _p)%R).
Notation r57 := ((r47 * _q)%R).
Notation r52 := ((r53 + r57)%R).
Lemma a4 : r44 = r52.
Proof. first [ring | unfold float2R, Float1, Defs.F2R; simpl; unfold Z.pow_pos; simpl; field]. Qed.
Lemma b4 : r44 = r52.
 apply a4.
Qed.
Definition f1 := Float2 (-89) (-3).
Definition f2 := Float2 (89) (-3).
Definition i1 := makepairF f1 f2.
Notation p1 := (BND _p i1). (* BND(p, [-11.125, 11.125]) *)
Definition f3 := Float2 (-15) (-3).
Definition f4 := Float2 (15) (-3).
Definition i2 := makepairF f3 f4.
Notation p2 := (BND _q i2). (* BND(q, [-1.875, 1.875]) *)
Definition s2 := (p1 /\ p2).
Definition f5 := Float2 (-813702877652374769) (-108).
Definition f6 := Float2 (813702877652374769) (-108).
Definition i3 := makepairF f5 f6.
Notation p3 := (BND r1 i3). (* BND(p1 - p_exact, [-2.50742e-15, 2.50742e-15]) *)
Definition s10 := (not p3).
Definition f7 := Float2 (-585952308504433553) (-110).
Definition f8 := Float2 (585952308504433553) (-110).
Definition i4 := makepairF f7 f8.
Notation p4 := (BND r27 i4). (* BND(q1 - q_exact, [-4.51401e-16, 4.51401e-16]) *)
Definition s11 := (not p4).
Definition s9 := (s10 \/ s11).
Notation r58 := ((Rabs _ap)%R).
Definition f9 := Float2 (0) (0).
Definition f10 := Float2 (9007199254740991) (971).
Definition i5 := makepairF f9 f10.
Notation p5 := (BND r58 i5). (* BND(|ap|, [0, 1.79769e+308]) *)
Definition s12 := (not p5).
Definition s8 := (s9 \/ s12).
Notation r59 := ((Rabs _bq)%R).
Notation p6 := (BND r59 i5). (* BND(|bq|, [0, 1.79769e+308]) *)
Definition s13 := (not p6).
Definition s7 := (s8 \/ s13).
Notation r60 := ((Rabs _p1)%R).
Notation p7 := (BND r60 i5). (* BND(|p1|, [0, 1.79769e+308]) *)
Definition s14 := (not p7).
Definition s6 := (s7 \/ s14).
Notation r61 := ((Rabs _gp)%R).
Notation p8 := (BND r61 i5). (* BND(|gp|, [0, 1.79769e+308]) *)
Definition s15 := (not p8).
Definition s5 := (s6 \/ s15).
Notation r62 := ((Rabs _dq)%R).
Notation p9 := (BND r62 i5). (* BND(|dq|, [0, 1.79769e+308]) *)
Definition s16 := (not p9).
Definition s4 := (s5 \/ s16).
Notation r63 := ((Rabs _q1)%R).
Notation p10 := (BND r63 i5). (* BND(|q1|, [0, 1.79769e+308]) *)
Definition s17 := (not p10).
Definition s3 := (s4 \/ s17).
Definition s1 := (s2 /\ s3).
Definition s18 := (s9 \/ s17).
Definition s20 := (s9 \/ s14).
Definition s19 := (s20 \/ s17).
Definition s22 := (s20 \/ s15).
Definition s21 := (s22 \/ s17).
Definition s26 := (s9 \/ s13).
Definition s25 := (s26 \/ s14).
Definition s24 := (s25 \/ s15).
Definition s23 := (s24 \/ s17).
Definition s28 := (s24 \/ s16).
Definition s27 := (s28 \/ s17).
Lemma l9 : s1 -> s3.
Proof.
 intros h0.
 assert (h1 := h0).
 exact (proj2 h1).
Qed.
Definition f11 := Float2 (6185712514271605) (-49).
Definition i6 := makepairF f9 f11.
Notation p11 := (BND r58 i6). (* BND(|ap|, [0, 10.988]) *)
Notation p12 := (ABS _ap i6). (* ABS(ap, [0, 10.988]) *)
Definition f12 := Float2 (-6185712514271605) (-49).
Definition i7 := makepairF f12 f11.
Notation p13 := (BND _ap i7). (* BND(ap, [-10.988, 10.988]) *)
Definition f13 := Float2 (-49485700114172843) (-52).
Definition f14 := Float2 (49485700114172843) (-52).
Definition i8 := makepairF f13 f14.
Notation p14 := (BND _ap_ideal i8). (* BND(ap_ideal, [-10.988, 10.988]) *)
Definition f15 := Float2 (1) (-1).
Definition f16 := Float2 (8896305638502983) (-53).
Definition i9 := makepairF f15 f16.
Notation p15 := (BND _delta i9). (* BND(delta, [0.5, 0.987688]) *)
Lemma t1 : p15.
Proof.
 refine (constant2 _ i9 _) ; finalize.
Qed.
Lemma l14 : s1 -> p15 (* BND(delta, [0.5, 0.987688]) *).
Proof.
 intros h0.
 apply t1.
Qed.
Lemma l16 : s1 -> s2.
Proof.
 intros h0.
 assert (h1 := h0).
 exact (proj1 h1).
Qed.
Lemma l15 : s1 -> p1 (* BND(p, [-11.125, 11.125]) *).
Proof.
 intros h0.
 assert (h1 := l16 h0).
 exact (proj1 h1).
Qed.
Lemma t2 : p15 -> p1 -> p14.
Proof.
 intros h0 h1.
 refine (mul_po _delta _p i9 i1 i8 h0 h1 _) ; finalize.
Qed.
Lemma l13 : s1 -> p14 (* BND(ap_ideal, [-10.988, 10.988]) *).
Proof.
 intros h0.
 assert (h1 := l14 h0).
 assert (h2 := l15 h0).
 apply t2. exact h1. exact h2.
Qed.
Lemma t3 : p14 -> p13.
Proof.
 intros h0.
 refine (float_round_ne _ _ _ap_ideal i8 i7 h0 _) ; finalize.
Qed.
Lemma l12 : s1 -> p13 (* BND(ap, [-10.988, 10.988]) *).
Proof.
 intros h0.
 assert (h1 := l13 h0).
 apply t3. exact h1.
Qed.
Lemma t4 : p13 -> p12.
Proof.
 intros h0.
 refine (abs_of_bnd_o _ap i7 i6 h0 _) ; finalize.
Qed.
Lemma l11 : s1 -> p12 (* ABS(ap, [0, 10.988]) *).
Proof.
 intros h0.
 assert (h1 := l12 h0).
 apply t4. exact h1.
Qed.
Lemma t5 : p12 -> p11.
Proof.
 intros h0.
 refine (uabs_of_abs _ap i6 h0) ; finalize.
Qed.
Lemma l10 : s1 -> p11 (* BND(|ap|, [0, 10.988]) *).
Proof.
 intros h0.
 assert (h1 := l11 h0).
 apply t5. exact h1.
Qed.
Lemma l8 : s1 -> s27.
Proof.
 intros h0.
 assert (h1 := l9 h0).
 assert (h2 := l10 h0).
 refine (simplify (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 2%nat i5))) (Tatom false (Abnd 3%nat i5))) (Tatom false (Abnd 4%nat i5))) (Tatom false (Abnd 5%nat i5))) (Tatom false (Abnd 6%nat i5))) (Tatom false (Abnd 7%nat i5))) (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 3%nat i5))) (Tatom false (Abnd 4%nat i5))) (Tatom false (Abnd 5%nat i5))) (Tatom false (Abnd 6%nat i5))) (Tatom false (Abnd 7%nat i5))) (Abnd 2%nat i6) (List.cons r1 (List.cons r27 (List.cons r58 (List.cons r59 (List.cons r60 (List.cons r61 (List.cons r62 (List.cons r63 List.nil)))))))) h2 h1 _) ; finalize.
Qed.
Definition f17 := Float2 (8340286536096547) (-52).
Definition i10 := makepairF f9 f17.
Notation p16 := (BND r62 i10). (* BND(|dq|, [0, 1.85192]) *)
Notation p17 := (ABS _dq i10). (* ABS(dq, [0, 1.85192]) *)
Definition f18 := Float2 (-8340286536096547) (-52).
Definition i11 := makepairF f18 f17.
Notation p18 := (BND _dq i11). (* BND(dq, [-1.85192, 1.85192]) *)
Notation p19 := (BND _dq_ideal i11). (* BND(dq_ideal, [-1.85192, 1.85192]) *)
Lemma l21 : s1 -> p2 (* BND(q, [-1.875, 1.875]) *).
Proof.
 intros h0.
 assert (h1 := l16 h0).
 exact (proj2 h1).
Qed.
Lemma t6 : p15 -> p2 -> p19.
Proof.
 intros h0 h1.
 refine (mul_po _delta _q i9 i2 i11 h0 h1 _) ; finalize.
Qed.
Lemma l20 : s1 -> p19 (* BND(dq_ideal, [-1.85192, 1.85192]) *).
Proof.
 intros h0.
 assert (h1 := l14 h0).
 assert (h2 := l21 h0).
 apply t6. exact h1. exact h2.
Qed.
Lemma t7 : p19 -> p18.
Proof.
 intros h0.
 refine (float_round_ne _ _ _dq_ideal i11 i11 h0 _) ; finalize.
Qed.
Lemma l19 : s1 -> p18 (* BND(dq, [-1.85192, 1.85192]) *).
Proof.
 intros h0.
 assert (h1 := l20 h0).
 apply t7. exact h1.
Qed.
Lemma t8 : p18 -> p17.
Proof.
 intros h0.
 refine (abs_of_bnd_o _dq i11 i10 h0 _) ; finalize.
Qed.
Lemma l18 : s1 -> p17 (* ABS(dq, [0, 1.85192]) *).
Proof.
 intros h0.
 assert (h1 := l19 h0).
 apply t8. exact h1.
Qed.
Lemma t9 : p17 -> p16.
Proof.
 intros h0.
 refine (uabs_of_abs _dq i10 h0) ; finalize.
Qed.
Lemma l17 : s1 -> p16 (* BND(|dq|, [0, 1.85192]) *).
Proof.
 intros h0.
 assert (h1 := l18 h0).
 apply t9. exact h1.
Qed.
Lemma l7 : s1 -> s23.
Proof.
 intros h0.
 assert (h1 := l8 h0).
 assert (h2 := l17 h0).
 refine (simplify (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 2%nat i5))) (Tatom false (Abnd 3%nat i5))) (Tatom false (Abnd 4%nat i5))) (Tatom false (Abnd 5%nat i5))) (Tatom false (Abnd 6%nat i5))) (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 2%nat i5))) (Tatom false (Abnd 3%nat i5))) (Tatom false (Abnd 4%nat i5))) (Tatom false (Abnd 6%nat i5))) (Abnd 5%nat i10) (List.cons r1 (List.cons r27 (List.cons r59 (List.cons r60 (List.cons r61 (List.cons r62 (List.cons r63 List.nil))))))) h2 h1 _) ; finalize.
Qed.
Definition f19 := Float2 (8299920028430715) (-52).
Definition i12 := makepairF f9 f19.
Notation p20 := (BND r59 i12). (* BND(|bq|, [0, 1.84295]) *)
Notation p21 := (ABS _bq i12). (* ABS(bq, [0, 1.84295]) *)
Definition f20 := Float2 (-8299920028430715) (-52).
Definition i13 := makepairF f20 f19.
Notation p22 := (BND _bq i13). (* BND(bq, [-1.84295, 1.84295]) *)
Notation p23 := (BND _bq_ideal i13). (* BND(bq_ideal, [-1.84295, 1.84295]) *)
Definition f21 := Float2 (-553328001895381) (-49).
Definition f22 := Float2 (-1) (-1).
Definition i14 := makepairF f21 f22.
Notation p24 := (BND _beta i14). (* BND(beta, [-0.982908, -0.5]) *)
Lemma t10 : p24.
Proof.
 refine (constant2 _ i14 _) ; finalize.
Qed.
Lemma l26 : s1 -> p24 (* BND(beta, [-0.982908, -0.5]) *).
Proof.
 intros h0.
 apply t10.
Qed.
Lemma t11 : p24 -> p2 -> p23.
Proof.
 intros h0 h1.
 refine (mul_no _beta _q i14 i2 i13 h0 h1 _) ; finalize.
Qed.
Lemma l25 : s1 -> p23 (* BND(bq_ideal, [-1.84295, 1.84295]) *).
Proof.
 intros h0.
 assert (h1 := l26 h0).
 assert (h2 := l21 h0).
 apply t11. exact h1. exact h2.
Qed.
Lemma t12 : p23 -> p22.
Proof.
 intros h0.
 refine (float_round_ne _ _ _bq_ideal i13 i13 h0 _) ; finalize.
Qed.
Lemma l24 : s1 -> p22 (* BND(bq, [-1.84295, 1.84295]) *).
Proof.
 intros h0.
 assert (h1 := l25 h0).
 apply t12. exact h1.
Qed.
Lemma t13 : p22 -> p21.
Proof.
 intros h0.
 refine (abs_of_bnd_o _bq i13 i12 h0 _) ; finalize.
Qed.
Lemma l23 : s1 -> p21 (* ABS(bq, [0, 1.84295]) *).
Proof.
 intros h0.
 assert (h1 := l24 h0).
 apply t13. exact h1.
Qed.
Lemma t14 : p21 -> p20.
Proof.
 intros h0.
 refine (uabs_of_abs _bq i12 h0) ; finalize.
Qed.
Lemma l22 : s1 -> p20 (* BND(|bq|, [0, 1.84295]) *).
Proof.
 intros h0.
 assert (h1 := l23 h0).
 apply t14. exact h1.
Qed.
Lemma l6 : s1 -> s21.
Proof.
 intros h0.
 assert (h1 := l7 h0).
 assert (h2 := l22 h0).
 refine (simplify (Ttree false (Ttree false (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 2%nat i5))) (Tatom false (Abnd 3%nat i5))) (Tatom false (Abnd 4%nat i5))) (Tatom false (Abnd 5%nat i5))) (Ttree false (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 3%nat i5))) (Tatom false (Abnd 4%nat i5))) (Tatom false (Abnd 5%nat i5))) (Abnd 2%nat i12) (List.cons r1 (List.cons r27 (List.cons r59 (List.cons r60 (List.cons r61 (List.cons r63 List.nil)))))) h2 h1 _) ; finalize.
Qed.
Definition f23 := Float2 (4989671900046959) (-54).
Definition i15 := makepairF f9 f23.
Notation p25 := (BND r61 i15). (* BND(|gp|, [0, 0.276982]) *)
Notation p26 := (ABS _gp i15). (* ABS(gp, [0, 0.276982]) *)
Definition f24 := Float2 (-4989671900046959) (-54).
Definition i16 := makepairF f24 f23.
Notation p27 := (BND _gp i16). (* BND(gp, [-0.276982, 0.276982]) *)
Notation p28 := (BND _gp_ideal i16). (* BND(gp_ideal, [-0.276982, 0.276982]) *)
Definition f25 := Float2 (1) (-6).
Definition f26 := Float2 (7176157339393379) (-58).
Definition i17 := makepairF f25 f26.
Notation p29 := (BND _gamma i17). (* BND(gamma, [0.015625, 0.0248973]) *)
Lemma t15 : p29.
Proof.
 refine (constant2 _ i17 _) ; finalize.
Qed.
Lemma l31 : s1 -> p29 (* BND(gamma, [0.015625, 0.0248973]) *).
Proof.
 intros h0.
 apply t15.
Qed.
Lemma t16 : p29 -> p1 -> p28.
Proof.
 intros h0 h1.
 refine (mul_po _gamma _p i17 i1 i16 h0 h1 _) ; finalize.
Qed.
Lemma l30 : s1 -> p28 (* BND(gp_ideal, [-0.276982, 0.276982]) *).
Proof.
 intros h0.
 assert (h1 := l31 h0).
 assert (h2 := l15 h0).
 apply t16. exact h1. exact h2.
Qed.
Lemma t17 : p28 -> p27.
Proof.
 intros h0.
 refine (float_round_ne _ _ _gp_ideal i16 i16 h0 _) ; finalize.
Qed.
Lemma l29 : s1 -> p27 (* BND(gp, [-0.276982, 0.276982]) *).
Proof.
 intros h0.
 assert (h1 := l30 h0).
 apply t17. exact h1.
Qed.
Lemma t18 : p27 -> p26.
Proof.
 intros h0.
 refine (abs_of_bnd_o _gp i16 i15 h0 _) ; finalize.
Qed.
Lemma l28 : s1 -> p26 (* ABS(gp, [0, 0.276982]) *).
Proof.
 intros h0.
 assert (h1 := l29 h0).
 apply t18. exact h1.
Qed.
Lemma t19 : p26 -> p25.
Proof.
 intros h0.
 refine (uabs_of_abs _gp i15 h0) ; finalize.
Qed.
Lemma l27 : s1 -> p25 (* BND(|gp|, [0, 0.276982]) *).
Proof.
 intros h0.
 assert (h1 := l28 h0).
 apply t19. exact h1.
Qed.
Lemma l5 : s1 -> s19.
Proof.
 intros h0.
 assert (h1 := l6 h0).
 assert (h2 := l27 h0).
 refine (simplify (Ttree false (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 2%nat i5))) (Tatom false (Abnd 3%nat i5))) (Tatom false (Abnd 4%nat i5))) (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 2%nat i5))) (Tatom false (Abnd 4%nat i5))) (Abnd 3%nat i15) (List.cons r1 (List.cons r27 (List.cons r60 (List.cons r61 (List.cons r63 List.nil))))) h2 h1 _) ; finalize.
Qed.
Definition f27 := Float2 (1805800629456361) (-47).
Definition i18 := makepairF f9 f27.
Notation p30 := (BND r60 i18). (* BND(|p1|, [0, 12.831]) *)
Notation p31 := (ABS _p1 i18). (* ABS(p1, [0, 12.831]) *)
Definition f28 := Float2 (-1805800629456361) (-47).
Definition i19 := makepairF f28 f27.
Notation p32 := (BND _p1 i19). (* BND(p1, [-12.831, 12.831]) *)
Definition f29 := Float2 (-14446405035650889) (-50).
Definition f30 := Float2 (14446405035650889) (-50).
Definition i20 := makepairF f29 f30.
Notation p33 := (BND r3 i20). (* BND(ap + bq, [-12.831, 12.831]) *)
Definition f31 := Float2 (-2074980007107679) (-50).
Definition f32 := Float2 (2074980007107679) (-50).
Definition i21 := makepairF f31 f32.
Notation p34 := (BND _bq i21). (* BND(bq, [-1.84295, 1.84295]) *)
Lemma t20 : p13 -> p34 -> p33.
Proof.
 intros h0 h1.
 refine (add _ap _bq i7 i21 i20 h0 h1 _) ; finalize.
Qed.
Lemma l35 : s1 -> p33 (* BND(ap + bq, [-12.831, 12.831]) *).
Proof.
 intros h0.
 assert (h1 := l12 h0).
 assert (h2 := l24 h0).
 apply t20. exact h1. refine (subset _bq i13 i21 h2 _) ; finalize.
Qed.
Lemma t21 : p33 -> p32.
Proof.
 intros h0.
 refine (float_round_ne _ _ r3 i20 i19 h0 _) ; finalize.
Qed.
Lemma l34 : s1 -> p32 (* BND(p1, [-12.831, 12.831]) *).
Proof.
 intros h0.
 assert (h1 := l35 h0).
 apply t21. exact h1.
Qed.
Lemma t22 : p32 -> p31.
Proof.
 intros h0.
 refine (abs_of_bnd_o _p1 i19 i18 h0 _) ; finalize.
Qed.
Lemma l33 : s1 -> p31 (* ABS(p1, [0, 12.831]) *).
Proof.
 intros h0.
 assert (h1 := l34 h0).
 apply t22. exact h1.
Qed.
Lemma t23 : p31 -> p30.
Proof.
 intros h0.
 refine (uabs_of_abs _p1 i18 h0) ; finalize.
Qed.
Lemma l32 : s1 -> p30 (* BND(|p1|, [0, 12.831]) *).
Proof.
 intros h0.
 assert (h1 := l33 h0).
 apply t23. exact h1.
Qed.
Lemma l4 : s1 -> s18.
Proof.
 intros h0.
 assert (h1 := l5 h0).
 assert (h2 := l32 h0).
 refine (simplify (Ttree false (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 2%nat i5))) (Tatom false (Abnd 3%nat i5))) (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 3%nat i5))) (Abnd 2%nat i18) (List.cons r1 (List.cons r27 (List.cons r60 (List.cons r63 List.nil)))) h2 h1 _) ; finalize.
Qed.
Definition f33 := Float2 (4793852255554143) (-51).
Definition i22 := makepairF f9 f33.
Notation p35 := (BND r63 i22). (* BND(|q1|, [0, 2.1289]) *)
Notation p36 := (ABS _q1 i22). (* ABS(q1, [0, 2.1289]) *)
Definition f34 := Float2 (-4793852255554143) (-51).
Definition i23 := makepairF f34 f33.
Notation p37 := (BND _q1 i23). (* BND(q1, [-2.1289, 2.1289]) *)
Definition f35 := Float2 (-38350818044433147) (-54).
Definition f36 := Float2 (38350818044433147) (-54).
Definition i24 := makepairF f35 f36.
Notation p38 := (BND r29 i24). (* BND(gp + dq, [-2.1289, 2.1289]) *)
Lemma t24 : p27 -> p18 -> p38.
Proof.
 intros h0 h1.
 refine (add _gp _dq i16 i11 i24 h0 h1 _) ; finalize.
Qed.
Lemma l39 : s1 -> p38 (* BND(gp + dq, [-2.1289, 2.1289]) *).
Proof.
 intros h0.
 assert (h1 := l29 h0).
 assert (h2 := l19 h0).
 apply t24. exact h1. exact h2.
Qed.
Lemma t25 : p38 -> p37.
Proof.
 intros h0.
 refine (float_round_ne _ _ r29 i24 i23 h0 _) ; finalize.
Qed.
Lemma l38 : s1 -> p37 (* BND(q1, [-2.1289, 2.1289]) *).
Proof.
 intros h0.
 assert (h1 := l39 h0).
 apply t25. exact h1.
Qed.
Lemma t26 : p37 -> p36.
Proof.
 intros h0.
 refine (abs_of_bnd_o _q1 i23 i22 h0 _) ; finalize.
Qed.
Lemma l37 : s1 -> p36 (* ABS(q1, [0, 2.1289]) *).
Proof.
 intros h0.
 assert (h1 := l38 h0).
 apply t26. exact h1.
Qed.
Lemma t27 : p36 -> p35.
Proof.
 intros h0.
 refine (uabs_of_abs _q1 i22 h0) ; finalize.
Qed.
Lemma l36 : s1 -> p35 (* BND(|q1|, [0, 2.1289]) *).
Proof.
 intros h0.
 assert (h1 := l37 h0).
 apply t27. exact h1.
Qed.
Lemma l3 : s1 -> s9.
Proof.
 intros h0.
 assert (h1 := l4 h0).
 assert (h2 := l36 h0).
 refine (simplify (Ttree false (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 2%nat i5))) (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Abnd 2%nat i22) (List.cons r1 (List.cons r27 (List.cons r63 List.nil))) h2 h1 _) ; finalize.
Qed.
Notation p39 := (BND r23 i3). (* BND(p1 - p1_ideal + (p1_ideal - p_exact), [-2.50742e-15, 2.50742e-15]) *)
Definition f37 := Float2 (-17) (-53).
Definition f38 := Float2 (17) (-53).
Definition i25 := makepairF f37 f38.
Notation p40 := (BND r24 i25). (* BND(p1 - p1_ideal, [-1.88738e-15, 1.88738e-15]) *)
Notation r65 := ((_p1 - r3)%R).
Notation r66 := ((r3 - _p1_ideal)%R).
Notation r64 := ((r65 + r66)%R).
Notation p41 := (BND r64 i25). (* BND(p1 - (ap + bq) + (ap + bq - p1_ideal), [-1.88738e-15, 1.88738e-15]) *)
Definition f39 := Float2 (-1) (-50).
Definition f40 := Float2 (1) (-50).
Definition i26 := makepairF f39 f40.
Notation p42 := (BND r65 i26). (* BND(p1 - (ap + bq), [-8.88178e-16, 8.88178e-16]) *)
Definition f41 := Float2 (1) (4).
Definition i27 := makepairF f9 f41.
Notation p43 := (ABS r3 i27). (* ABS(ap + bq, [0, 16]) *)
Definition f42 := Float2 (-1) (4).
Definition i28 := makepairF f42 f41.
Notation p44 := (BND r3 i28). (* BND(ap + bq, [-16, 16]) *)
Lemma t28 : p44 -> p43.
Proof.
 intros h0.
 refine (abs_of_bnd_o r3 i28 i27 h0 _) ; finalize.
Qed.
Lemma l45 : s1 -> p43 (* ABS(ap + bq, [0, 16]) *).
Proof.
 intros h0.
 assert (h1 := l35 h0).
 apply t28. refine (subset r3 i20 i28 h1 _) ; finalize.
Qed.
Lemma t29 : p43 -> p42.
Proof.
 intros h0.
 refine (float_absolute_wide_ne _ _ r3 i27 i26 h0 _) ; finalize.
Qed.
Lemma l44 : s1 -> p42 (* BND(p1 - (ap + bq), [-8.88178e-16, 8.88178e-16]) *).
Proof.
 intros h0.
 assert (h1 := l45 h0).
 apply t29. exact h1.
Qed.
Definition f43 := Float2 (-9) (-53).
Definition f44 := Float2 (9) (-53).
Definition i29 := makepairF f43 f44.
Notation p45 := (BND r66 i29). (* BND(ap + bq - p1_ideal, [-9.99201e-16, 9.99201e-16]) *)
Notation r68 := ((_ap - _ap_ideal)%R).
Notation r69 := ((_bq - _bq_ideal)%R).
Notation r67 := ((r68 + r69)%R).
Notation p46 := (BND r67 i29). (* BND(ap - ap_ideal + (bq - bq_ideal), [-9.99201e-16, 9.99201e-16]) *)
Notation p47 := (BND r68 i26). (* BND(ap - ap_ideal, [-8.88178e-16, 8.88178e-16]) *)
Notation p48 := (ABS _ap_ideal i27). (* ABS(ap_ideal, [0, 16]) *)
Definition f45 := Float2 (1) (0).
Definition i30 := makepairF f15 f45.
Notation p49 := (ABS _delta i30). (* ABS(delta, [0.5, 1]) *)
Notation p50 := (BND _delta i30). (* BND(delta, [0.5, 1]) *)
Lemma t30 : p50 -> p49.
Proof.
 intros h0.
 refine (abs_of_bnd_p _delta i30 i30 h0 _) ; finalize.
Qed.
Lemma l50 : s1 -> p49 (* ABS(delta, [0.5, 1]) *).
Proof.
 intros h0.
 assert (h1 := l14 h0).
 apply t30. refine (subset _delta i9 i30 h1 _) ; finalize.
Qed.
Notation p51 := (ABS _p i27). (* ABS(p, [0, 16]) *)
Notation p52 := (BND _p i28). (* BND(p, [-16, 16]) *)
Lemma t31 : p52 -> p51.
Proof.
 intros h0.
 refine (abs_of_bnd_o _p i28 i27 h0 _) ; finalize.
Qed.
Lemma l51 : s1 -> p51 (* ABS(p, [0, 16]) *).
Proof.
 intros h0.
 assert (h1 := l15 h0).
 apply t31. refine (subset _p i1 i28 h1 _) ; finalize.
Qed.
Lemma t32 : p49 -> p51 -> p48.
Proof.
 intros h0 h1.
 refine (mul_aa _delta _p i30 i27 i27 h0 h1 _) ; finalize.
Qed.
Lemma l49 : s1 -> p48 (* ABS(ap_ideal, [0, 16]) *).
Proof.
 intros h0.
 assert (h1 := l50 h0).
 assert (h2 := l51 h0).
 apply t32. exact h1. exact h2.
Qed.
Lemma t33 : p48 -> p47.
Proof.
 intros h0.
 refine (float_absolute_wide_ne _ _ _ap_ideal i27 i26 h0 _) ; finalize.
Qed.
Lemma l48 : s1 -> p47 (* BND(ap - ap_ideal, [-8.88178e-16, 8.88178e-16]) *).
Proof.
 intros h0.
 assert (h1 := l49 h0).
 apply t33. exact h1.
Qed.
Definition f46 := Float2 (-1) (-53).
Definition f47 := Float2 (1) (-53).
Definition i31 := makepairF f46 f47.
Notation p53 := (BND r69 i31). (* BND(bq - bq_ideal, [-1.11022e-16, 1.11022e-16]) *)
Definition f48 := Float2 (1) (1).
Definition i32 := makepairF f9 f48.
Notation p54 := (ABS _bq_ideal i32). (* ABS(bq_ideal, [0, 2]) *)
Notation p55 := (ABS _beta i30). (* ABS(beta, [0.5, 1]) *)
Definition f49 := Float2 (-1) (0).
Definition i33 := makepairF f49 f22.
Notation p56 := (BND _beta i33). (* BND(beta, [-1, -0.5]) *)
Lemma t34 : p56 -> p55.
Proof.
 intros h0.
 refine (abs_of_bnd_n _beta i33 i30 h0 _) ; finalize.
Qed.
Lemma l54 : s1 -> p55 (* ABS(beta, [0.5, 1]) *).
Proof.
 intros h0.
 assert (h1 := l26 h0).
 apply t34. refine (subset _beta i14 i33 h1 _) ; finalize.
Qed.
Notation p57 := (ABS _q i32). (* ABS(q, [0, 2]) *)
Definition f50 := Float2 (-1) (1).
Definition i34 := makepairF f50 f48.
Notation p58 := (BND _q i34). (* BND(q, [-2, 2]) *)
Lemma t35 : p58 -> p57.
Proof.
 intros h0.
 refine (abs_of_bnd_o _q i34 i32 h0 _) ; finalize.
Qed.
Lemma l55 : s1 -> p57 (* ABS(q, [0, 2]) *).
Proof.
 intros h0.
 assert (h1 := l21 h0).
 apply t35. refine (subset _q i2 i34 h1 _) ; finalize.
Qed.
Lemma t36 : p55 -> p57 -> p54.
Proof.
 intros h0 h1.
 refine (mul_aa _beta _q i30 i32 i32 h0 h1 _) ; finalize.
Qed.
Lemma l53 : s1 -> p54 (* ABS(bq_ideal, [0, 2]) *).
Proof.
 intros h0.
 assert (h1 := l54 h0).
 assert (h2 := l55 h0).
 apply t36. exact h1. exact h2.
Qed.
Lemma t37 : p54 -> p53.
Proof.
 intros h0.
 refine (float_absolute_wide_ne _ _ _bq_ideal i32 i31 h0 _) ; finalize.
Qed.
Lemma l52 : s1 -> p53 (* BND(bq - bq_ideal, [-1.11022e-16, 1.11022e-16]) *).
Proof.
 intros h0.
 assert (h1 := l53 h0).
 apply t37. exact h1.
Qed.
Lemma t38 : p47 -> p53 -> p46.
Proof.
 intros h0 h1.
 refine (add r68 r69 i26 i31 i29 h0 h1 _) ; finalize.
Qed.
Lemma l47 : s1 -> p46 (* BND(ap - ap_ideal + (bq - bq_ideal), [-9.99201e-16, 9.99201e-16]) *).
Proof.
 intros h0.
 assert (h1 := l48 h0).
 assert (h2 := l52 h0).
 apply t38. exact h1. exact h2.
Qed.
Lemma t39 : p46 -> p45.
Proof.
 intros h0.
 refine (add_mibs _ _ _ _ i29 h0) ; finalize.
Qed.
Lemma l46 : s1 -> p45 (* BND(ap + bq - p1_ideal, [-9.99201e-16, 9.99201e-16]) *).
Proof.
 intros h0.
 assert (h1 := l47 h0).
 apply t39. exact h1.
Qed.
Lemma t40 : p42 -> p45 -> p41.
Proof.
 intros h0 h1.
 refine (add r65 r66 i26 i29 i25 h0 h1 _) ; finalize.
Qed.
Lemma l43 : s1 -> p41 (* BND(p1 - (ap + bq) + (ap + bq - p1_ideal), [-1.88738e-15, 1.88738e-15]) *).
Proof.
 intros h0.
 assert (h1 := l44 h0).
 assert (h2 := l46 h0).
 apply t40. exact h1. exact h2.
Qed.
Lemma t41 : p41 -> p40.
Proof.
 intros h0.
 refine (sub_xals _ _ _ i25 h0) ; finalize.
Qed.
Lemma l42 : s1 -> p40 (* BND(p1 - p1_ideal, [-1.88738e-15, 1.88738e-15]) *).
Proof.
 intros h0.
 assert (h1 := l43 h0).
 apply t41. exact h1.
Qed.
Definition f51 := Float2 (-201213328329987313) (-108).
Definition f52 := Float2 (201213328329987313) (-108).
Definition i35 := makepairF f51 f52.
Notation p59 := (BND r26 i35). (* BND(p1_ideal - p_exact, [-6.20036e-16, 6.20036e-16]) *)
Notation p60 := (BND r45 i35). (* BND(-3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840 * p + 725368870011116500311633037363284098815934157950200991855380254176979494545 / 14681737584036205971792085335481670627880553447618287576963763260000045253935184688946610176 * q, [-6.20036e-16, 6.20036e-16]) *)
Definition f53 := Float2 (-342302048992417441) (-109).
Definition f54 := Float2 (342302048992417441) (-109).
Definition i36 := makepairF f53 f54.
Notation p61 := (BND r46 i36). (* BND(-3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840 * p, [-5.274e-16, 5.274e-16]) *)
Definition f55 := Float2 (-492299576078982387) (-113).
Definition f56 := Float2 (-1) (-55).
Definition i37 := makepairF f55 f56.
Notation p62 := (BND r47 i37). (* BND(-3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840, [-4.74067e-17, -2.77556e-17]) *)
Definition f57 := Float2 (-369604275970387067) (93).
Definition f58 := Float2 (-1) (151).
Definition i38 := makepairF f57 f58.
Notation p63 := (BND r48 i38). (* BND(-3660383455318603984232747923630239280051403617, [-3.66038e+45, -2.8545e+45]) *)
Lemma t42 : p63.
Proof.
 refine (constant1 _ i38 _) ; finalize.
Qed.
Lemma l60 : s1 -> p63 (* BND(-3660383455318603984232747923630239280051403617, [-3.66038e+45, -2.8545e+45]) *).
Proof.
 intros h0.
 apply t42.
Qed.
Definition f59 := Float2 (216395025847299009) (148).
Definition f60 := Float2 (1) (206).
Definition i39 := makepairF f59 f60.
Notation p64 := (BND r18 i39). (* BND(77212325338401015504689204853976229175880009829288981131427840, [7.72123e+61, 1.02844e+62]) *)
Lemma t43 : p64.
Proof.
 refine (constant1 _ i39 _) ; finalize.
Qed.
Lemma l61 : s1 -> p64 (* BND(77212325338401015504689204853976229175880009829288981131427840, [7.72123e+61, 1.02844e+62]) *).
Proof.
 intros h0.
 apply t43.
Qed.
Lemma t44 : p63 -> p64 -> p62.
Proof.
 intros h0 h1.
 refine (div_np r48 r18 i38 i39 i37 h0 h1 _) ; finalize.
Qed.
Lemma l59 : s1 -> p62 (* BND(-3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840, [-4.74067e-17, -2.77556e-17]) *).
Proof.
 intros h0.
 assert (h1 := l60 h0).
 assert (h2 := l61 h0).
 apply t44. exact h1. exact h2.
Qed.
Lemma t45 : p62 -> p1 -> p61.
Proof.
 intros h0 h1.
 refine (mul_no r47 _p i37 i1 i36 h0 h1 _) ; finalize.
Qed.
Lemma l58 : s1 -> p61 (* BND(-3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840 * p, [-5.274e-16, 5.274e-16]) *).
Proof.
 intros h0.
 assert (h1 := l59 h0).
 assert (h2 := l15 h0).
 apply t45. exact h1. exact h2.
Qed.
Definition f61 := Float2 (-60124607667557185) (-109).
Definition f62 := Float2 (60124607667557185) (-109).
Definition i40 := makepairF f61 f62.
Notation p65 := (BND r49 i40). (* BND(725368870011116500311633037363284098815934157950200991855380254176979494545 / 14681737584036205971792085335481670627880553447618287576963763260000045253935184688946610176 * q, [-9.26366e-17, 9.26366e-17]) *)
Definition f63 := Float2 (1) (-55).
Definition f64 := Float2 (513063318763154645) (-113).
Definition i41 := makepairF f63 f64.
Notation p66 := (BND r50 i41). (* BND(725368870011116500311633037363284098815934157950200991855380254176979494545 / 14681737584036205971792085335481670627880553447618287576963763260000045253935184688946610176, [2.77556e-17, 4.94062e-17]) *)
Definition f65 := Float2 (1) (248).
Definition f66 := Float2 (462231711760798775) (190).
Definition i42 := makepairF f65 f66.
Notation p67 := (BND r51 i42). (* BND(725368870011116500311633037363284098815934157950200991855380254176979494545, [4.52313e+74, 7.25369e+74]) *)
Lemma t46 : p67.
Proof.
 refine (constant1 _ i42 _) ; finalize.
Qed.
Lemma l64 : s1 -> p67 (* BND(725368870011116500311633037363284098815934157950200991855380254176979494545, [4.52313e+74, 7.25369e+74]) *).
Proof.
 intros h0.
 apply t46.
Qed.
Definition f67 := Float2 (259674031016758811) (245).
Definition f68 := Float2 (1) (303).
Definition i43 := makepairF f67 f68.
Notation p68 := (BND r22 i43). (* BND(14681737584036205971792085335481670627880553447618287576963763260000045253935184688946610176, [1.46817e+91, 1.62963e+91]) *)
Lemma t47 : p68.
Proof.
 refine (constant1 _ i43 _) ; finalize.
Qed.
Lemma l65 : s1 -> p68 (* BND(14681737584036205971792085335481670627880553447618287576963763260000045253935184688946610176, [1.46817e+91, 1.62963e+91]) *).
Proof.
 intros h0.
 apply t47.
Qed.
Lemma t48 : p67 -> p68 -> p66.
Proof.
 intros h0 h1.
 refine (div_pp r51 r22 i42 i43 i41 h0 h1 _) ; finalize.
Qed.
Lemma l63 : s1 -> p66 (* BND(725368870011116500311633037363284098815934157950200991855380254176979494545 / 14681737584036205971792085335481670627880553447618287576963763260000045253935184688946610176, [2.77556e-17, 4.94062e-17]) *).
Proof.
 intros h0.
 assert (h1 := l64 h0).
 assert (h2 := l65 h0).
 apply t48. exact h1. exact h2.
Qed.
Lemma t49 : p66 -> p2 -> p65.
Proof.
 intros h0 h1.
 refine (mul_po r50 _q i41 i2 i40 h0 h1 _) ; finalize.
Qed.
Lemma l62 : s1 -> p65 (* BND(725368870011116500311633037363284098815934157950200991855380254176979494545 / 14681737584036205971792085335481670627880553447618287576963763260000045253935184688946610176 * q, [-9.26366e-17, 9.26366e-17]) *).
Proof.
 intros h0.
 assert (h1 := l63 h0).
 assert (h2 := l21 h0).
 apply t49. exact h1. exact h2.
Qed.
Lemma t50 : p61 -> p65 -> p60.
Proof.
 intros h0 h1.
 refine (add r46 r49 i36 i40 i35 h0 h1 _) ; finalize.
Qed.
Lemma l57 : s1 -> p60 (* BND(-3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840 * p + 725368870011116500311633037363284098815934157950200991855380254176979494545 / 14681737584036205971792085335481670627880553447618287576963763260000045253935184688946610176 * q, [-6.20036e-16, 6.20036e-16]) *).
Proof.
 intros h0.
 assert (h1 := l58 h0).
 assert (h2 := l62 h0).
 apply t50. exact h1. exact h2.
Qed.
Definition i44 := makepairF f9 f9.
Notation p69 := (REL r26 r45 i44). (* REL(p1_ideal - p_exact, -3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840 * p + 725368870011116500311633037363284098815934157950200991855380254176979494545 / 14681737584036205971792085335481670627880553447618287576963763260000045253935184688946610176 * q, [0, 0]) *)
Notation p70 := (r26 = r45). (* EQL(p1_ideal - p_exact, -3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840 * p + 725368870011116500311633037363284098815934157950200991855380254176979494545 / 14681737584036205971792085335481670627880553447618287576963763260000045253935184688946610176 * q) *)
Lemma t51 : p70.
Proof.
 refine (b3) ; finalize.
Qed.
Lemma l67 : s1 -> p70 (* EQL(p1_ideal - p_exact, -3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840 * p + 725368870011116500311633037363284098815934157950200991855380254176979494545 / 14681737584036205971792085335481670627880553447618287576963763260000045253935184688946610176 * q) *).
Proof.
 intros h0.
 apply t51.
Qed.
Notation p71 := (REL r45 r45 i44). (* REL(-3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840 * p + 725368870011116500311633037363284098815934157950200991855380254176979494545 / 14681737584036205971792085335481670627880553447618287576963763260000045253935184688946610176 * q, -3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840 * p + 725368870011116500311633037363284098815934157950200991855380254176979494545 / 14681737584036205971792085335481670627880553447618287576963763260000045253935184688946610176 * q, [0, 0]) *)
Lemma t52 : p71.
Proof.
 refine (rel_refl r45 i44 _) ; finalize.
Qed.
Lemma l68 : s1 -> p71 (* REL(-3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840 * p + 725368870011116500311633037363284098815934157950200991855380254176979494545 / 14681737584036205971792085335481670627880553447618287576963763260000045253935184688946610176 * q, -3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840 * p + 725368870011116500311633037363284098815934157950200991855380254176979494545 / 14681737584036205971792085335481670627880553447618287576963763260000045253935184688946610176 * q, [0, 0]) *).
Proof.
 intros h0.
 apply t52.
Qed.
Lemma t53 : p70 -> p71 -> p69.
Proof.
 intros h0 h1.
 refine (rel_rewrite_1 r26 r45 r45 i44 h0 h1) ; finalize.
Qed.
Lemma l66 : s1 -> p69 (* REL(p1_ideal - p_exact, -3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840 * p + 725368870011116500311633037363284098815934157950200991855380254176979494545 / 14681737584036205971792085335481670627880553447618287576963763260000045253935184688946610176 * q, [0, 0]) *).
Proof.
 intros h0.
 assert (h1 := l67 h0).
 assert (h2 := l68 h0).
 apply t53. exact h1. exact h2.
Qed.
Lemma t54 : p60 -> p69 -> p59.
Proof.
 intros h0 h1.
 refine (bnd_of_bnd_rel_o r26 r45 i35 i44 i35 h0 h1 _) ; finalize.
Qed.
Lemma l56 : s1 -> p59 (* BND(p1_ideal - p_exact, [-6.20036e-16, 6.20036e-16]) *).
Proof.
 intros h0.
 assert (h1 := l57 h0).
 assert (h2 := l66 h0).
 apply t54. exact h1. exact h2.
Qed.
Lemma t55 : p40 -> p59 -> p39.
Proof.
 intros h0 h1.
 refine (add r24 r26 i25 i35 i3 h0 h1 _) ; finalize.
Qed.
Lemma l41 : s1 -> p39 (* BND(p1 - p1_ideal + (p1_ideal - p_exact), [-2.50742e-15, 2.50742e-15]) *).
Proof.
 intros h0.
 assert (h1 := l42 h0).
 assert (h2 := l56 h0).
 apply t55. exact h1. exact h2.
Qed.
Notation p72 := (REL r1 r23 i44). (* REL(p1 - p_exact, p1 - p1_ideal + (p1_ideal - p_exact), [0, 0]) *)
Notation p73 := (r1 = r23). (* EQL(p1 - p_exact, p1 - p1_ideal + (p1_ideal - p_exact)) *)
Lemma t56 : p73.
Proof.
 refine (b1) ; finalize.
Qed.
Lemma l70 : s1 -> p73 (* EQL(p1 - p_exact, p1 - p1_ideal + (p1_ideal - p_exact)) *).
Proof.
 intros h0.
 apply t56.
Qed.
Notation p74 := (REL r23 r23 i44). (* REL(p1 - p1_ideal + (p1_ideal - p_exact), p1 - p1_ideal + (p1_ideal - p_exact), [0, 0]) *)
Lemma t57 : p74.
Proof.
 refine (rel_refl r23 i44 _) ; finalize.
Qed.
Lemma l71 : s1 -> p74 (* REL(p1 - p1_ideal + (p1_ideal - p_exact), p1 - p1_ideal + (p1_ideal - p_exact), [0, 0]) *).
Proof.
 intros h0.
 apply t57.
Qed.
Lemma t58 : p73 -> p74 -> p72.
Proof.
 intros h0 h1.
 refine (rel_rewrite_1 r1 r23 r23 i44 h0 h1) ; finalize.
Qed.
Lemma l69 : s1 -> p72 (* REL(p1 - p_exact, p1 - p1_ideal + (p1_ideal - p_exact), [0, 0]) *).
Proof.
 intros h0.
 assert (h1 := l70 h0).
 assert (h2 := l71 h0).
 apply t58. exact h1. exact h2.
Qed.
Lemma t59 : p39 -> p72 -> p3.
Proof.
 intros h0 h1.
 refine (bnd_of_bnd_rel_o r1 r23 i3 i44 i3 h0 h1 _) ; finalize.
Qed.
Lemma l40 : s1 -> p3 (* BND(p1 - p_exact, [-2.50742e-15, 2.50742e-15]) *).
Proof.
 intros h0.
 assert (h1 := l41 h0).
 assert (h2 := l69 h0).
 apply t59. exact h1. exact h2.
Qed.
Lemma l2 : s1 -> s11.
Proof.
 intros h0.
 assert (h1 := l3 h0).
 assert (h2 := l40 h0).
 refine (simplify (Ttree false (Tatom false (Abnd 0%nat i3)) (Tatom false (Abnd 1%nat i4))) (Tatom false (Abnd 1%nat i4)) (Abnd 0%nat i3) (List.cons r1 (List.cons r27 List.nil)) h2 h1 _) ; finalize.
Qed.
Notation p75 := (BND r41 i4). (* BND(q1 - q1_ideal + (q1_ideal - q_exact), [-4.51401e-16, 4.51401e-16]) *)
Definition f69 := Float2 (-13) (-55).
Definition f70 := Float2 (13) (-55).
Definition i45 := makepairF f69 f70.
Notation p76 := (BND r42 i45). (* BND(q1 - q1_ideal, [-3.60822e-16, 3.60822e-16]) *)
Notation r71 := ((_q1 - r29)%R).
Notation r72 := ((r29 - _q1_ideal)%R).
Notation r70 := ((r71 + r72)%R).
Notation p77 := (BND r70 i45). (* BND(q1 - (gp + dq) + (gp + dq - q1_ideal), [-3.60822e-16, 3.60822e-16]) *)
Definition f71 := Float2 (-1) (-52).
Definition f72 := Float2 (1) (-52).
Definition i46 := makepairF f71 f72.
Notation p78 := (BND r71 i46). (* BND(q1 - (gp + dq), [-2.22045e-16, 2.22045e-16]) *)
Definition f73 := Float2 (1) (2).
Definition i47 := makepairF f9 f73.
Notation p79 := (ABS r29 i47). (* ABS(gp + dq, [0, 4]) *)
Definition f74 := Float2 (-1) (2).
Definition i48 := makepairF f74 f73.
Notation p80 := (BND r29 i48). (* BND(gp + dq, [-4, 4]) *)
Lemma t60 : p80 -> p79.
Proof.
 intros h0.
 refine (abs_of_bnd_o r29 i48 i47 h0 _) ; finalize.
Qed.
Lemma l77 : s1 -> p79 (* ABS(gp + dq, [0, 4]) *).
Proof.
 intros h0.
 assert (h1 := l39 h0).
 apply t60. refine (subset r29 i24 i48 h1 _) ; finalize.
Qed.
Lemma t61 : p79 -> p78.
Proof.
 intros h0.
 refine (float_absolute_wide_ne _ _ r29 i47 i46 h0 _) ; finalize.
Qed.
Lemma l76 : s1 -> p78 (* BND(q1 - (gp + dq), [-2.22045e-16, 2.22045e-16]) *).
Proof.
 intros h0.
 assert (h1 := l77 h0).
 apply t61. exact h1.
Qed.
Definition f75 := Float2 (-5) (-55).
Definition f76 := Float2 (5) (-55).
Definition i49 := makepairF f75 f76.
Notation p81 := (BND r72 i49). (* BND(gp + dq - q1_ideal, [-1.38778e-16, 1.38778e-16]) *)
Notation r74 := ((_gp - _gp_ideal)%R).
Notation r75 := ((_dq - _dq_ideal)%R).
Notation r73 := ((r74 + r75)%R).
Notation p82 := (BND r73 i49). (* BND(gp - gp_ideal + (dq - dq_ideal), [-1.38778e-16, 1.38778e-16]) *)
Definition i50 := makepairF f56 f63.
Notation p83 := (BND r74 i50). (* BND(gp - gp_ideal, [-2.77556e-17, 2.77556e-17]) *)
Definition i51 := makepairF f9 f15.
Notation p84 := (ABS _gp_ideal i51). (* ABS(gp_ideal, [0, 0.5]) *)
Definition f77 := Float2 (1) (-5).
Definition i52 := makepairF f25 f77.
Notation p85 := (ABS _gamma i52). (* ABS(gamma, [0.015625, 0.03125]) *)
Notation p86 := (BND _gamma i52). (* BND(gamma, [0.015625, 0.03125]) *)
Lemma t62 : p86 -> p85.
Proof.
 intros h0.
 refine (abs_of_bnd_p _gamma i52 i52 h0 _) ; finalize.
Qed.
Lemma l82 : s1 -> p85 (* ABS(gamma, [0.015625, 0.03125]) *).
Proof.
 intros h0.
 assert (h1 := l31 h0).
 apply t62. refine (subset _gamma i17 i52 h1 _) ; finalize.
Qed.
Lemma t63 : p85 -> p51 -> p84.
Proof.
 intros h0 h1.
 refine (mul_aa _gamma _p i52 i27 i51 h0 h1 _) ; finalize.
Qed.
Lemma l81 : s1 -> p84 (* ABS(gp_ideal, [0, 0.5]) *).
Proof.
 intros h0.
 assert (h1 := l82 h0).
 assert (h2 := l51 h0).
 apply t63. exact h1. exact h2.
Qed.
Lemma t64 : p84 -> p83.
Proof.
 intros h0.
 refine (float_absolute_wide_ne _ _ _gp_ideal i51 i50 h0 _) ; finalize.
Qed.
Lemma l80 : s1 -> p83 (* BND(gp - gp_ideal, [-2.77556e-17, 2.77556e-17]) *).
Proof.
 intros h0.
 assert (h1 := l81 h0).
 apply t64. exact h1.
Qed.
Notation p87 := (BND r75 i31). (* BND(dq - dq_ideal, [-1.11022e-16, 1.11022e-16]) *)
Notation p88 := (ABS _dq_ideal i32). (* ABS(dq_ideal, [0, 2]) *)
Lemma t65 : p49 -> p57 -> p88.
Proof.
 intros h0 h1.
 refine (mul_aa _delta _q i30 i32 i32 h0 h1 _) ; finalize.
Qed.
Lemma l84 : s1 -> p88 (* ABS(dq_ideal, [0, 2]) *).
Proof.
 intros h0.
 assert (h1 := l50 h0).
 assert (h2 := l55 h0).
 apply t65. exact h1. exact h2.
Qed.
Lemma t66 : p88 -> p87.
Proof.
 intros h0.
 refine (float_absolute_wide_ne _ _ _dq_ideal i32 i31 h0 _) ; finalize.
Qed.
Lemma l83 : s1 -> p87 (* BND(dq - dq_ideal, [-1.11022e-16, 1.11022e-16]) *).
Proof.
 intros h0.
 assert (h1 := l84 h0).
 apply t66. exact h1.
Qed.
Lemma t67 : p83 -> p87 -> p82.
Proof.
 intros h0 h1.
 refine (add r74 r75 i50 i31 i49 h0 h1 _) ; finalize.
Qed.
Lemma l79 : s1 -> p82 (* BND(gp - gp_ideal + (dq - dq_ideal), [-1.38778e-16, 1.38778e-16]) *).
Proof.
 intros h0.
 assert (h1 := l80 h0).
 assert (h2 := l83 h0).
 apply t67. exact h1. exact h2.
Qed.
Lemma t68 : p82 -> p81.
Proof.
 intros h0.
 refine (add_mibs _ _ _ _ i49 h0) ; finalize.
Qed.
Lemma l78 : s1 -> p81 (* BND(gp + dq - q1_ideal, [-1.38778e-16, 1.38778e-16]) *).
Proof.
 intros h0.
 assert (h1 := l79 h0).
 apply t68. exact h1.
Qed.
Lemma t69 : p78 -> p81 -> p77.
Proof.
 intros h0 h1.
 refine (add r71 r72 i46 i49 i45 h0 h1 _) ; finalize.
Qed.
Lemma l75 : s1 -> p77 (* BND(q1 - (gp + dq) + (gp + dq - q1_ideal), [-3.60822e-16, 3.60822e-16]) *).
Proof.
 intros h0.
 assert (h1 := l76 h0).
 assert (h2 := l78 h0).
 apply t69. exact h1. exact h2.
Qed.
Lemma t70 : p77 -> p76.
Proof.
 intros h0.
 refine (sub_xals _ _ _ i45 h0) ; finalize.
Qed.
Lemma l74 : s1 -> p76 (* BND(q1 - q1_ideal, [-3.60822e-16, 3.60822e-16]) *).
Proof.
 intros h0.
 assert (h1 := l75 h0).
 apply t70. exact h1.
Qed.
Definition f78 := Float2 (-117577947257901969) (-110).
Definition f79 := Float2 (117577947257901969) (-110).
Definition i53 := makepairF f78 f79.
Notation p89 := (BND r44 i53). (* BND(q1_ideal - q_exact, [-9.05788e-17, 9.05788e-17]) *)
Notation p90 := (BND r52 i53). (* BND(-6671878411859531223066906417473 / 43890125504277088739791682231712132520374330982400 * p + -3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840 * q, [-9.05788e-17, 9.05788e-17]) *)
Definition f80 := Float2 (-274404264298809) (-107).
Definition f81 := Float2 (274404264298809) (-107).
Definition i54 := makepairF f80 f81.
Notation p91 := (BND r53 i54). (* BND(-6671878411859531223066906417473 / 43890125504277088739791682231712132520374330982400 * p, [-1.69115e-18, 1.69115e-18]) *)
Definition f82 := Float2 (-1578595318213373) (-113).
Definition f83 := Float2 (-1) (-63).
Definition i55 := makepairF f82 f83.
Notation p92 := (BND r54 i55). (* BND(-6671878411859531223066906417473 / 43890125504277088739791682231712132520374330982400, [-1.52013e-19, -1.0842e-19]) *)
Definition f84 := Float2 (-1481454606069195) (52).
Definition f85 := Float2 (-1) (102).
Definition i56 := makepairF f84 f85.
Notation p93 := (BND r55 i56). (* BND(-6671878411859531223066906417473, [-6.67188e+30, -5.0706e+30]) *)
Lemma t71 : p93.
Proof.
 refine (constant1 _ i56 _) ; finalize.
Qed.
Lemma l89 : s1 -> p93 (* BND(-6671878411859531223066906417473, [-6.67188e+30, -5.0706e+30]) *).
Proof.
 intros h0.
 apply t71.
Qed.
Definition f86 := Float2 (8452930697160117) (112).
Definition f87 := Float2 (1) (165).
Definition i57 := makepairF f86 f87.
Notation p94 := (BND r56 i57). (* BND(43890125504277088739791682231712132520374330982400, [4.38901e+49, 4.67681e+49]) *)
Lemma t72 : p94.
Proof.
 refine (constant1 _ i57 _) ; finalize.
Qed.
Lemma l90 : s1 -> p94 (* BND(43890125504277088739791682231712132520374330982400, [4.38901e+49, 4.67681e+49]) *).
Proof.
 intros h0.
 apply t72.
Qed.
Lemma t73 : p93 -> p94 -> p92.
Proof.
 intros h0 h1.
 refine (div_np r55 r56 i56 i57 i55 h0 h1 _) ; finalize.
Qed.
Lemma l88 : s1 -> p92 (* BND(-6671878411859531223066906417473 / 43890125504277088739791682231712132520374330982400, [-1.52013e-19, -1.0842e-19]) *).
Proof.
 intros h0.
 assert (h1 := l89 h0).
 assert (h2 := l90 h0).
 apply t73. exact h1. exact h2.
Qed.
Lemma t74 : p92 -> p1 -> p91.
Proof.
 intros h0 h1.
 refine (mul_no r54 _p i55 i1 i54 h0 h1 _) ; finalize.
Qed.
Lemma l87 : s1 -> p91 (* BND(-6671878411859531223066906417473 / 43890125504277088739791682231712132520374330982400 * p, [-1.69115e-18, 1.69115e-18]) *).
Proof.
 intros h0.
 assert (h1 := l88 h0).
 assert (h2 := l15 h0).
 apply t74. exact h1. exact h2.
Qed.
Definition f88 := Float2 (-115382713143511497) (-110).
Definition f89 := Float2 (115382713143511497) (-110).
Definition i58 := makepairF f88 f89.
Notation p95 := (BND r57 i58). (* BND(-3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840 * q, [-8.88876e-17, 8.88876e-17]) *)
Lemma t75 : p62 -> p2 -> p95.
Proof.
 intros h0 h1.
 refine (mul_no r47 _q i37 i2 i58 h0 h1 _) ; finalize.
Qed.
Lemma l91 : s1 -> p95 (* BND(-3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840 * q, [-8.88876e-17, 8.88876e-17]) *).
Proof.
 intros h0.
 assert (h1 := l59 h0).
 assert (h2 := l21 h0).
 apply t75. exact h1. exact h2.
Qed.
Lemma t76 : p91 -> p95 -> p90.
Proof.
 intros h0 h1.
 refine (add r53 r57 i54 i58 i53 h0 h1 _) ; finalize.
Qed.
Lemma l86 : s1 -> p90 (* BND(-6671878411859531223066906417473 / 43890125504277088739791682231712132520374330982400 * p + -3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840 * q, [-9.05788e-17, 9.05788e-17]) *).
Proof.
 intros h0.
 assert (h1 := l87 h0).
 assert (h2 := l91 h0).
 apply t76. exact h1. exact h2.
Qed.
Notation p96 := (REL r44 r52 i44). (* REL(q1_ideal - q_exact, -6671878411859531223066906417473 / 43890125504277088739791682231712132520374330982400 * p + -3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840 * q, [0, 0]) *)
Notation p97 := (r44 = r52). (* EQL(q1_ideal - q_exact, -6671878411859531223066906417473 / 43890125504277088739791682231712132520374330982400 * p + -3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840 * q) *)
Lemma t77 : p97.
Proof.
 refine (b4) ; finalize.
Qed.
Lemma l93 : s1 -> p97 (* EQL(q1_ideal - q_exact, -6671878411859531223066906417473 / 43890125504277088739791682231712132520374330982400 * p + -3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840 * q) *).
Proof.
 intros h0.
 apply t77.
Qed.
Notation p98 := (REL r52 r52 i44). (* REL(-6671878411859531223066906417473 / 43890125504277088739791682231712132520374330982400 * p + -3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840 * q, -6671878411859531223066906417473 / 43890125504277088739791682231712132520374330982400 * p + -3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840 * q, [0, 0]) *)
Lemma t78 : p98.
Proof.
 refine (rel_refl r52 i44 _) ; finalize.
Qed.
Lemma l94 : s1 -> p98 (* REL(-6671878411859531223066906417473 / 43890125504277088739791682231712132520374330982400 * p + -3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840 * q, -6671878411859531223066906417473 / 43890125504277088739791682231712132520374330982400 * p + -3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840 * q, [0, 0]) *).
Proof.
 intros h0.
 apply t78.
Qed.
Lemma t79 : p97 -> p98 -> p96.
Proof.
 intros h0 h1.
 refine (rel_rewrite_1 r44 r52 r52 i44 h0 h1) ; finalize.
Qed.
Lemma l92 : s1 -> p96 (* REL(q1_ideal - q_exact, -6671878411859531223066906417473 / 43890125504277088739791682231712132520374330982400 * p + -3660383455318603984232747923630239280051403617 / 77212325338401015504689204853976229175880009829288981131427840 * q, [0, 0]) *).
Proof.
 intros h0.
 assert (h1 := l93 h0).
 assert (h2 := l94 h0).
 apply t79. exact h1. exact h2.
Qed.
Lemma t80 : p90 -> p96 -> p89.
Proof.
 intros h0 h1.
 refine (bnd_of_bnd_rel_o r44 r52 i53 i44 i53 h0 h1 _) ; finalize.
Qed.
Lemma l85 : s1 -> p89 (* BND(q1_ideal - q_exact, [-9.05788e-17, 9.05788e-17]) *).
Proof.
 intros h0.
 assert (h1 := l86 h0).
 assert (h2 := l92 h0).
 apply t80. exact h1. exact h2.
Qed.
Lemma t81 : p76 -> p89 -> p75.
Proof.
 intros h0 h1.
 refine (add r42 r44 i45 i53 i4 h0 h1 _) ; finalize.
Qed.
Lemma l73 : s1 -> p75 (* BND(q1 - q1_ideal + (q1_ideal - q_exact), [-4.51401e-16, 4.51401e-16]) *).
Proof.
 intros h0.
 assert (h1 := l74 h0).
 assert (h2 := l85 h0).
 apply t81. exact h1. exact h2.
Qed.
Notation p99 := (REL r27 r41 i44). (* REL(q1 - q_exact, q1 - q1_ideal + (q1_ideal - q_exact), [0, 0]) *)
Notation p100 := (r27 = r41). (* EQL(q1 - q_exact, q1 - q1_ideal + (q1_ideal - q_exact)) *)
Lemma t82 : p100.
Proof.
 refine (b2) ; finalize.
Qed.
Lemma l96 : s1 -> p100 (* EQL(q1 - q_exact, q1 - q1_ideal + (q1_ideal - q_exact)) *).
Proof.
 intros h0.
 apply t82.
Qed.
Notation p101 := (REL r41 r41 i44). (* REL(q1 - q1_ideal + (q1_ideal - q_exact), q1 - q1_ideal + (q1_ideal - q_exact), [0, 0]) *)
Lemma t83 : p101.
Proof.
 refine (rel_refl r41 i44 _) ; finalize.
Qed.
Lemma l97 : s1 -> p101 (* REL(q1 - q1_ideal + (q1_ideal - q_exact), q1 - q1_ideal + (q1_ideal - q_exact), [0, 0]) *).
Proof.
 intros h0.
 apply t83.
Qed.
Lemma t84 : p100 -> p101 -> p99.
Proof.
 intros h0 h1.
 refine (rel_rewrite_1 r27 r41 r41 i44 h0 h1) ; finalize.
Qed.
Lemma l95 : s1 -> p99 (* REL(q1 - q_exact, q1 - q1_ideal + (q1_ideal - q_exact), [0, 0]) *).
Proof.
 intros h0.
 assert (h1 := l96 h0).
 assert (h2 := l97 h0).
 apply t84. exact h1. exact h2.
Qed.
Lemma t85 : p75 -> p99 -> p4.
Proof.
 intros h0 h1.
 refine (bnd_of_bnd_rel_o r27 r41 i4 i44 i4 h0 h1 _) ; finalize.
Qed.
Lemma l72 : s1 -> p4 (* BND(q1 - q_exact, [-4.51401e-16, 4.51401e-16]) *).
Proof.
 intros h0.
 assert (h1 := l73 h0).
 assert (h2 := l95 h0).
 apply t85. exact h1. exact h2.
Qed.
Lemma l1 : s1 -> False.
Proof.
 intros h0.
 assert (h1 := l2 h0).
 assert (h2 := l72 h0).
 refine (simplify (Tatom false (Abnd 0%nat i4)) Tfalse (Abnd 0%nat i4) (List.cons r27 List.nil) h2 h1 _) ; finalize.
Qed.
End Generated_by_Gappa.
End Gappa_N40.

Module Lifting_N40.
(* The lifting lemma of phi3-matrix in double (simpson-verify, issue 29): Phi, the invariant form Q and the one-step
   bound (Bp, Bq) are the harness's, exactly; Bp and Bq are Gappa's bound, proved in its own certificate.
   The float iterate is y_(k+1) = Phi y_k + e_k with |e_k| <= (Bp, Bq) while y_k stays in the box; the error
   d_k = y_k - Phi^k y_0 then obeys d_(k+1) = Phi d_k + e_k, and sqrt(Q(d_n)) <= n eps. *)
Open Scope R_scope.

Definition a := (76261713085606223321819560886785958185474988892094483350567777 / 77212325338401015504689204853976229175880009829288981131427840).
Definition b := (-14430797040402638931187821021425337574080128090175933931085415253899271220252790495036876433 / 14681737584036205971792085335481670627880553447618287576963763260000045253935184688946610176).
Definition c := (30329780330904584893144624612461 / 1218195697213405835340518441381800).
Definition d := (76261713085606223321819560886785958185474988892094483350567777 / 77212325338401015504689204853976229175880009829288981131427840).
Definition wp := (1 / 1).
Definition wq := (360769926010065973279695525535633439352003202254398348277135381347481780506319762375921910825 / 9138389603952863355721862387340674471650393371702563304643471975878778544611589419526258688).
Definition Bp := (813702877652374769 / 324518553658426726783156020576256).
Definition Bq := (585952308504433553 / 1298074214633706907132624082305024).
Definition eps := (2399461502472653 / 633825300114114700748351602688).

Definition Q (x y : R) := wp * x * x + wq * y * y.

Lemma Q_nonneg : forall x y, 0 <= Q x y.
Proof. intros. unfold Q, wp, wq. nra. Qed.

Lemma invariant : forall x y, Q (a * x + b * y) (c * x + d * y) = Q x y.
Proof. intros. unfold Q, a, b, c, d, wp, wq. field. Qed.

Lemma one_step : forall ex ey, -Bp <= ex <= Bp -> -Bq <= ey <= Bq -> Q ex ey <= eps * eps.
Proof. intros ex ey Hx Hy. unfold Q, wp, wq, Bp, Bq, eps in *. nra. Qed.

Lemma cauchy : forall x1 y1 x2 y2, wp * x1 * x2 + wq * y1 * y2 <= sqrt (Q x1 y1) * sqrt (Q x2 y2).
Proof.
  intros. rewrite <- sqrt_mult by apply Q_nonneg.
  destruct (Rle_or_lt (wp * x1 * x2 + wq * y1 * y2) 0) as [H | H].
  - apply Rle_trans with 0; [exact H | apply sqrt_pos].
  - apply Rsqr_incr_0_var; [| apply sqrt_pos].
    rewrite Rsqr_sqrt by (apply Rmult_le_pos; apply Q_nonneg).
    assert (W : 0 <= wp * wq) by (unfold wp, wq; lra).
    pose proof (Rle_0_sqr (x1 * y2 - x2 * y1)) as Sq. unfold Rsqr in Sq.
    assert (0 <= wp * wq * ((x1 * y2 - x2 * y1) * (x1 * y2 - x2 * y1))) by (apply Rmult_le_pos; assumption).
    unfold Rsqr, Q. nra.
Qed.

Lemma triangle : forall x1 y1 x2 y2, sqrt (Q (x1 + x2) (y1 + y2)) <= sqrt (Q x1 y1) + sqrt (Q x2 y2).
Proof.
  intros. apply Rsqr_incr_0_var; [| apply Rplus_le_le_0_compat; apply sqrt_pos].
  rewrite Rsqr_sqrt by apply Q_nonneg.
  pose proof (cauchy x1 y1 x2 y2) as C.
  pose proof (sqrt_sqrt (Q x1 y1) (Q_nonneg x1 y1)) as S1.
  pose proof (sqrt_sqrt (Q x2 y2) (Q_nonneg x2 y2)) as S2.
  unfold Rsqr. unfold Q in *. nra.
Qed.

Theorem lifting : forall (dp dq ep eq : nat -> R),
  dp 0%nat = 0 -> dq 0%nat = 0 ->
  (forall k, dp (S k) = a * dp k + b * dq k + ep k) ->
  (forall k, dq (S k) = c * dp k + d * dq k + eq k) ->
  (forall k, -Bp <= ep k <= Bp /\ -Bq <= eq k <= Bq) ->
  forall n, sqrt (Q (dp n) (dq n)) <= INR n * eps.
Proof.
  intros dp dq ep eq H0p H0q Hp Hq He n. induction n as [| n IH].
  - rewrite H0p, H0q. unfold Q. simpl. replace (wp * 0 * 0 + wq * 0 * 0) with 0 by ring. rewrite sqrt_0. lra.
  - rewrite Hp, Hq, S_INR.
    eapply Rle_trans; [apply triangle |].
    rewrite invariant.
    assert (sqrt (Q (ep n) (eq n)) <= eps).
    { destruct (He n) as [Hx Hy].
      rewrite <- (sqrt_square eps) by (unfold eps; lra).
      apply sqrt_le_1_alt. apply one_step; assumption. }
    lra.
Qed.
End Lifting_N40.

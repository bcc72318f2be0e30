(* Ruling a root out (see rootless.mli).

   Most rays miss most surfaces, and Poly's search pays for its critical
   points, each to full precision, before it finds no change of sign.
   [proved] shows more cheaply, for degrees 2 to 4, that the polynomial
   keeps one sign on [[lo, hi]]:

   - past Fujiwara's bound on the roots (below) the leading term
     outweighs the others, so only the part within it is looked at;
   - the roots of the second derivative cut that part into pieces where
     the polynomial is convex or concave; on a concave piece its least
     value is at an end, on a convex one it lies above the tangents at
     both ends, whose meeting point, if too low, is where the piece is
     cut in two (a step that narrows in on the least value fast).

   It answers [true] only when every bound clears a margin, 1e-10 of the
   sum of the terms' magnitudes, far above the rounding of Horner's rule
   (below 1e-15 of that sum for degree 4), of its own arithmetic and of
   the pieces' ends. The search's values are the polynomial's up to that
   rounding, so it too would find no change of sign and no zero. *)

(* the larger, keeping nan (as [Float.max], which calls C for the sign
   of a zero: none here, the values are magnitudes) *)
let[@inline] mag_max (a : float) (b : float) = if a > b || a <> a then a else b

let[@inline] value c4 c3 c2 c1 c0 t = (((((((c4 *. t) +. c3) *. t) +. c2) *. t) +. c1) *. t) +. c0
let[@inline] slope c4 c3 c2 c1 t = (((((4. *. c4 *. t) +. (3. *. c3)) *. t) +. (2. *. c2)) *. t) +. c1

(* the sum of the terms' magnitudes at t *)
let[@inline] size c4 c3 c2 c1 c0 t =
  value (Float.abs c4) (Float.abs c3) (Float.abs c2) (Float.abs c1) (Float.abs c0) (Float.abs t)

let margin = 1e-10

(* Whether [sg] times the polynomial stays above [m] on [[l, h]], given
   its values [fl] and [fh] there (above [m]), its slopes [dl] and [dh],
   and the sign of its second derivative [curve] (none inside). *)
let[@inline] piece_clear c4 c3 c2 c1 c0 sg curve l fl dl h fh dh m =
  if curve <= 0. || (curve > 0. && (dl >= 0. || dh <= 0.)) then
    (* concave, or convex and monotone: least at an end *)
    true
  else if not (curve > 0.) then false
  else begin
    (* convex, falling then rising *)
    let l = ref l and fl = ref fl and dl = ref dl and h = ref h and fh = ref fh and dh = ref dh in
    let verdict = ref 0 and cuts = ref 0 in
    while !verdict = 0 do
      (* where the tangents at the ends meet, [s] past [l] *)
      let len = !h -. !l in
      let s = (!fl -. !fh +. (!dh *. len)) /. (!dh -. !dl) in
      (* kept in the piece (a nan, from an overflow, fails below) *)
      let s = if s >= len then len else if s <= 0. then 0. else s in
      if !fl +. (!dl *. s) > m then verdict := 1
      else if !cuts = 8 then verdict := 2
      else begin
        incr cuts;
        let t = !l +. s in
        let ft = sg *. value c4 c3 c2 c1 c0 t and dt = sg *. slope c4 c3 c2 c1 t in
        if not (ft > m) then verdict := 2
        else if dt >= 0. then (h := t; fh := ft; dh := dt)
        else (l := t; fl := ft; dl := dt)
      end
    done;
    !verdict = 1
  end

(* Fujiwara's bound on the roots' magnitudes, 2 max |c_(n-k) / c_n|^(1/k)
   over k = 1 .. n, a cube root rounded up to a square or fourth root
   (x^(1/3) is below the larger of the two): past it each term below the
   leading one is at most 2^-k of it, so the polynomial's magnitude stays
   above 2^-n times the leading term, 2^-(n+1) of the sum of the terms'
   magnitudes. *)
let[@inline] ratio c lead = Float.abs (c /. lead)
let[@inline] root3 x = let s = Float.sqrt x in if s >= 1. then s else Float.sqrt s
let[@inline] root4 x = Float.sqrt (Float.sqrt x)

let[@inline] fujiwara n c3 c2 c1 c0 lead =
  let m =
    if n = 4 then
      mag_max
        (mag_max (ratio c3 lead) (Float.sqrt (ratio c2 lead)))
        (mag_max (root3 (ratio c1 lead)) (root4 (ratio c0 lead)))
    else if n = 3 then mag_max (mag_max (ratio c2 lead) (Float.sqrt (ratio c1 lead))) (root3 (ratio c0 lead))
    else mag_max (ratio c1 lead) (Float.sqrt (ratio c0 lead))
  in
  2. *. m

let[@inline] proved n c4 c3 c2 c1 c0 lo hi =
  let lead = if n = 4 then c4 else if n = 3 then c3 else c2 in
  let b = fujiwara n c3 c2 c1 c0 lead in
  if lo > b || hi < -.b then true
  else begin
    (* the rest, [[lo', hi']]: past its ends, where they are the bound,
       the polynomial keeps the sign it has there *)
    let lo' = if lo > -.b then lo else -.b and hi' = if hi < b then hi else b in
    let f0 = value c4 c3 c2 c1 c0 lo' in
    let sg = if f0 > 0. then 1. else -1. in
    let f0 = sg *. f0 in
    (* the margin, from the terms' size where it is largest *)
    let m = margin *. size c4 c3 c2 c1 c0 (if -.lo' > hi' then lo' else hi') in
    f0 > m && lo' < hi'
    &&
    begin
      (* the second derivative qa t^2 + qb t + qc: its roots (in order:
         [u], [v]), and those inside (lo', hi') ([hi'] for none) *)
      let qa = 12. *. c4 and qb = 6. *. c3 and qc = 2. *. c2 in
      let disc = (qb *. qb) -. (4. *. qa *. qc) in
      let q = -0.5 *. if qb < 0. then qb -. Float.sqrt disc else qb +. Float.sqrt disc in
      let two = qa <> 0. && disc > 0. in
      let r1 = if two then q /. qa else if qa = 0. && qb <> 0. then -.qc /. qb else nan in
      let r2 = if two then qc /. q else r1 in
      let u = if r1 < r2 then r1 else r2 and v = if r1 < r2 then r2 else r1 in
      let b1 = if u > lo' && u < hi' then u else hi' and b2 = if v > lo' && v < hi' then v else hi' in
      let clear = ref true and l = ref lo' and fl = ref f0 in
      let dl = ref (sg *. slope c4 c3 c2 c1 lo') and k = ref 0 in
      while !clear && !k < 3 do
        let h = if !k = 0 then b1 else if !k = 1 then b2 else hi' in
        if h > !l && (h < hi' || !k = 2) then begin
          let fh = sg *. value c4 c3 c2 c1 c0 h and dh = sg *. slope c4 c3 c2 c1 h in
          (* the second derivative's sign on the piece, from where its
             middle lies against the roots (not from its value there,
             which is zero in the middle of a double root's pieces) *)
          let mid = 0.5 *. (!l +. h) in
          let curve =
            if two then if mid > u && mid < v then -.qa else qa
            else if qa <> 0. then qa
            else if qb <> 0. then if mid > r1 then qb else -.qb
            else qc
          in
          clear := fh > m && piece_clear c4 c3 c2 c1 c0 sg (sg *. curve) !l !fl !dl h fh dh m;
          l := h;
          fl := fh;
          dl := dh
        end;
        incr k
      done;
      !clear
    end
  end

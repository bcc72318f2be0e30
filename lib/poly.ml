let[@inline] newton3 a b c d t =
  let t = ref t in
  for _ = 1 to 3 do
    let f = (((a *. !t) +. b) *. !t +. c) *. !t +. d in
    let df = (((3. *. a *. !t) +. (2. *. b)) *. !t) +. c in
    if df <> 0. then
      let t' = !t -. (f /. df) in
      if Float.is_finite t' then t := t'
  done;
  !t

let cubic_roots a b c d =
  (* depressed cubic t = x - p/3 for x^3 + p x^2 + q x + r *)
  let p = b /. a and q = c /. a and r = d /. a in
  let p3 = p /. 3. in
  let qq = (q -. (p *. p3)) /. 3. in
  let rr = (((2. *. p3 *. p3) -. q) *. p3 +. r) /. 2. in
  (* x^3 + 3 qq x + 2 rr = 0 with x = t + p3 *)
  let disc = (rr *. rr) +. (qq *. qq *. qq) in
  let roots =
    if disc > 0. then
      let s = Float.sqrt disc in
      let u = Float.cbrt (-.rr +. s) and v = Float.cbrt (-.rr -. s) in
      [| u +. v -. p3 |]
    else if qq = 0. then [| -.p3 |]
    else
      let m = 2. *. Float.sqrt (-.qq) in
      let cosv = Float.max (-1.) (Float.min 1. (-.rr /. Float.sqrt (-.(qq *. qq *. qq)))) in
      let th = Float.acos cosv /. 3. in
      let k = 2. *. Float.pi /. 3. in
      [| (m *. Float.cos th) -. p3; (m *. Float.cos (th +. k)) -. p3; (m *. Float.cos (th -. k)) -. p3 |]
  in
  let roots = Array.map (newton3 a b c d) roots in
  Array.sort Float.compare roots;
  roots

let[@inline] eval a b c d e t = ((((((a *. t) +. b) *. t) +. c) *. t) +. d) *. t +. e
let[@inline] deriv a b c d t = ((((4. *. a *. t) +. (3. *. b)) *. t) +. (2. *. c)) *. t +. d

(* A root of the polynomial in [lo, hi] where fl and fh have opposite
   signs: Newton steps kept inside the shrinking bracket, bisection when a
   step leaves it. *)
let[@inline] bracketed a b c d e lo hi fl =
  let lo = ref lo and hi = ref hi and fl = ref fl in
  let t = ref (0.5 *. (!lo +. !hi)) in
  let n = ref 0 in
  while !n < 100 && !hi -. !lo > 1e-13 *. (1. +. Float.abs !t) do
    incr n;
    let f = eval a b c d e !t in
    if f = 0. then (lo := !t; hi := !t)
    else begin
      if (f < 0.) = (!fl < 0.) then (lo := !t; fl := f) else hi := !t;
      let df = deriv a b c d !t in
      let tn = if df <> 0. then !t -. (f /. df) else nan in
      t := if tn > !lo && tn < !hi then tn else 0.5 *. (!lo +. !hi)
    end
  done;
  !t

(* The critical points (roots of the derivative) split [lo, hi] into
   monotone pieces; the first piece whose ends differ in sign holds the
   first root. Written without arrays or lists: it runs per ray. *)
let first_quartic_root a b c d e lo hi =
  if not (hi > lo) then infinity
  else begin
    (* roots of 4a t^3 + 3b t^2 + 2c t + d, as in [cubic_roots]; absent
       ones are infinity *)
    let ca = 4. *. a and cb = 3. *. b and cc = 2. *. c in
    let p = cb /. ca and q = cc /. ca and r = d /. ca in
    let p3 = p /. 3. in
    let qq = (q -. (p *. p3)) /. 3. in
    let rr = ((((2. *. p3 *. p3) -. q) *. p3) +. r) /. 2. in
    let disc = (rr *. rr) +. (qq *. qq *. qq) in
    let r0, r1, r2 =
      if disc > 0. then
        let sd = Float.sqrt disc in
        (Float.cbrt (-.rr +. sd) +. Float.cbrt (-.rr -. sd) -. p3, infinity, infinity)
      else if qq = 0. then (-.p3, infinity, infinity)
      else
        let m = 2. *. Float.sqrt (-.qq) in
        let cosv = Float.max (-1.) (Float.min 1. (-.rr /. Float.sqrt (-.(qq *. qq *. qq)))) in
        let th = Float.acos cosv /. 3. in
        let k = 2. *. Float.pi /. 3. in
        ((m *. Float.cos th) -. p3, (m *. Float.cos (th +. k)) -. p3, (m *. Float.cos (th -. k)) -. p3)
    in
    let r0 = newton3 ca cb cc d r0 in
    let r1 = if r1 = infinity then r1 else newton3 ca cb cc d r1 in
    let r2 = if r2 = infinity then r2 else newton3 ca cb cc d r2 in
    (* sort the three *)
    let x0 = if r0 < r1 then r0 else r1 and x1 = if r0 < r1 then r1 else r0 in
    let y1 = if x1 < r2 then x1 else r2 and s2 = if x1 < r2 then r2 else x1 in
    let s0 = if x0 < y1 then x0 else y1 and s1 = if x0 < y1 then y1 else x0 in
    let result = ref infinity and prev = ref lo and k = ref 0 in
    while !result = infinity && !k < 4 do
      let q = match !k with 0 -> s0 | 1 -> s1 | 2 -> s2 | _ -> hi in
      if !k = 3 || (q > lo && q < hi) then begin
        let p = !prev in
        let fp = eval a b c d e p and fq = eval a b c d e q in
        if fq = 0. && q < hi then result := q
        else if (fp < 0.) <> (fq < 0.) && fp <> 0. then begin
          let t = bracketed a b c d e p q fp in
          if t > lo && t < hi then result := t
        end;
        prev := q
      end;
      incr k
    done;
    !result
  end

(* Polynomials of any degree, by their derivatives: the roots of the
   (k+1)-th derivative cut the line into pieces where the k-th is
   monotone, so each piece holds at most one of its roots, bracketed by a
   change of sign. Level k's coefficients (ascending) are at k * w in
   [d]. Each level's roots are made in increasing order when the level
   below asks for its next piece's end (see [next_root]), so that no
   critical point past the first root is looked for. *)
type scratch = {
  d : Float.Array.t;
  w : int;
  at : Float.Array.t;  (* per level: the start of its current piece *)
  value_at : Float.Array.t;  (* the level's value there *)
  out : Float.Array.t;  (* the level's last root made *)
  over : int array;  (* 1 once the level has made its last root *)
  top : Float.Array.t;
      (* at 0: the end of the search; at 1: where it stops looking (see
         [first_root_below]); at 2 and 3: the window asked for *)
}

let scratch max_degree =
  let w = max_degree + 1 in
  let a () = Float.Array.make w 0. in
  { d = Float.Array.make (w * w) 0.; w; at = a (); value_at = a (); out = a (); over = Array.make w 0;
    top = Float.Array.make 4 0. }

let root sc = Float.Array.unsafe_get sc.out 0

let[@inline] horner d base deg t =
  let acc = ref (Float.Array.unsafe_get d (base + deg)) in
  for m = deg - 1 downto 0 do
    acc := (!acc *. t) +. Float.Array.unsafe_get d (base + m)
  done;
  !acc

(* A root of level [k] (degree [deg]) in [lo, hi], where its values [fl]
   at [lo] and the other end differ in sign: Newton steps on its
   derivative (level k+1) kept inside the shrinking bracket, bisection
   when a step leaves it. *)
let root_between sc k deg lo hi fl =
  let d = sc.d and w = sc.w in
  let lo = ref lo and hi = ref hi and fl = ref fl in
  let t = ref (0.5 *. (!lo +. !hi)) and n = ref 0 in
  while !n < 100 && !hi -. !lo > 1e-14 *. (1. +. Float.abs !t) do
    incr n;
    let f = horner d (k * w) deg !t in
    if f = 0. then (lo := !t; hi := !t)
    else begin
      if (f < 0.) = (!fl < 0.) then (lo := !t; fl := f) else hi := !t;
      let df = horner d ((k + 1) * w) (deg - 1) !t in
      let tn = if df <> 0. then !t -. (f /. df) else nan in
      t := if tn > !lo && tn < !hi then tn else 0.5 *. (!lo +. !hi)
    end
  done;
  !t

(* the larger, keeping nan (as [Float.max], which calls C for the sign
   of a zero: none here, the values are magnitudes) *)
let[@inline] mag_max (a : float) (b : float) = if a > b || a <> a then a else b

(* Roots farther than this are not looked for (POV-Ray's largest
   intersection distance) *)
let reach = 1e7

let[@inline] g a i = Float.Array.unsafe_get a i

(* The sum of |c_i| reach^i below degree m, over reach^m (how far the
   terms below m can go where roots are looked for, in units of c_m's) *)
let below (eqn : Float.Array.t) m =
  let s = ref 0. and p = ref 1. in
  for i = m - 1 downto 0 do
    p := !p /. reach;
    s := !s +. (Float.abs (g eqn i) *. !p)
  done;
  !s

(* The next root of level [lv] (of [n]) into [sc.out], if one is left:
   the pieces run from the start of the search through the next roots of
   level [lv + 1] to its end; a root is a piece's end where the level is
   zero (but the search's end) or is found inside a piece whose ends'
   values differ in sign. *)
let rec next_root sc lv n =
  if Array.unsafe_get sc.over lv <> 0 then false
  else if lv = n - 1 then begin
    Array.unsafe_set sc.over lv 1;
    true
  end
  else begin
    let d = sc.d and w = sc.w and deg = n - lv in
    let found = ref false in
    (* a root past the stop is not wanted: no piece that starts there is
       searched *)
    if lv = 0 && g sc.at 0 >= g sc.top 1 then Array.unsafe_set sc.over 0 1;
    while (not !found) && Array.unsafe_get sc.over lv = 0 do
      let inner = next_root sc (lv + 1) n in
      let c = if inner then g sc.out (lv + 1) else g sc.top 0 in
      let fc = horner d (lv * w) deg c and fp = g sc.value_at lv in
      if fc = 0. && inner then begin
        Float.Array.unsafe_set sc.out lv c;
        found := true
      end
      else if fp <> 0. && (fp < 0.) <> (fc < 0.) then begin
        Float.Array.unsafe_set sc.out lv (root_between sc lv deg (g sc.at lv) c fp);
        found := true
      end;
      Float.Array.unsafe_set sc.at lv c;
      Float.Array.unsafe_set sc.value_at lv fc;
      if (not inner) || (lv = 0 && c >= g sc.top 1) then Array.unsafe_set sc.over lv 1
    done;
    !found
  end

(* the window and the stop come in [sc.top] (2: lo, 3: hi, 1: the
   stop): floats passed to a function too large to inline are boxed,
   and its callers are in every ray's path *)
let search sc (eqn : Float.Array.t) degree =
  let lo = g sc.top 2 and hi = g sc.top 3 and stop = g sc.top 1 in
  (* a leading term below the rounding of the others wherever a root is
     looked for is dropped: a direction component that is zero but for
     rounding (a rotation by 90 degrees) leaves such terms, whose roots,
     far out, are not the surface's *)
  let n = ref degree in
  while !n > 0 && Float.abs (g eqn !n) <= 1e-16 *. below eqn !n do decr n done;
  let n = !n in
  if n = 0 then false
  else begin
    (* every root lies within Cauchy's bound *)
    let lead = g eqn n in
    let bound = ref 0. in
    for m = 0 to n - 1 do
      bound := mag_max !bound (Float.abs (g eqn m /. lead))
    done;
    (* [Float.min] and [Float.max] as comparisons (they call C for the
       sign of a zero: [cap] is at least 1) *)
    let cap = 1. +. !bound in
    let cap = if cap < reach || cap <> cap then cap else reach in
    let hi = if hi < cap || hi <> hi then hi else cap in
    let lo = if lo > -.cap || lo <> lo then lo else -.cap in
    let below = if stop < hi then stop else hi in
    if not (lo < below) then false
    else if
      (* a miss ruled out more cheaply, with the search's answer *)
      n >= 2 && n <= 4
      && Rootless.proved n
           (if n = 4 then g eqn 4 else 0.)
           (if n >= 3 then g eqn 3 else 0.)
           (g eqn 2) (g eqn 1) (g eqn 0) lo below
    then false
    else begin
      let d = sc.d and w = sc.w in
      for m = 0 to n do
        Float.Array.unsafe_set d m (g eqn m)
      done;
      for k = 1 to n - 1 do
        for m = 0 to n - k do
          Float.Array.unsafe_set d ((k * w) + m) (float (m + 1) *. g d (((k - 1) * w) + m + 1))
        done
      done;
      (* level n-1 is linear: its root, if inside, is made now *)
      let base = (n - 1) * w in
      let t = -.g d base /. g d (base + 1) in
      Float.Array.unsafe_set sc.out (n - 1) t;
      Array.unsafe_set sc.over (n - 1) (if t > lo && t < hi then 0 else 1);
      for lv = 0 to n - 2 do
        Float.Array.unsafe_set sc.at lv lo;
        Float.Array.unsafe_set sc.value_at lv (horner d (lv * w) (n - lv) lo);
        Array.unsafe_set sc.over lv 0
      done;
      Float.Array.unsafe_set sc.top 0 hi;
      next_root sc 0 n
    end
  end

let[@inline] window sc lo hi stop =
  Float.Array.unsafe_set sc.top 2 lo;
  Float.Array.unsafe_set sc.top 3 hi;
  Float.Array.unsafe_set sc.top 1 stop

let[@inline] first_root_in sc eqn degree lo hi =
  window sc lo hi infinity;
  search sc eqn degree

let[@inline] first_root sc eqn degree lo =
  window sc lo infinity infinity;
  search sc eqn degree

let[@inline] first_root_below sc eqn degree lo stop =
  window sc lo infinity stop;
  search sc eqn degree && Float.Array.unsafe_get sc.out 0 < stop

(* {2 A cubic's roots in one pass}

   What [first_root_in] called again past each root finds, without
   finding the critical points again per root: those of a cubic in
   closed form, of a quadratic as [first_root_in] finds them (so a
   quadratic's and a line's roots are its, to the bit). *)

(* [reach]'s powers as [below] makes them *)
let p1 = 1. /. reach
let p2 = p1 /. reach
let p3 = p2 /. reach

let[@inline] cubic c3 c2 c1 c0 t = (((((c3 *. t) +. c2) *. t) +. c1) *. t) +. c0

(* [root_between] for a cubic (a dropped leading term is 0.: the same
   values) *)
let[@inline] cubic_between c3 c2 c1 c0 lo hi fl =
  let lo = ref lo and hi = ref hi and fl = ref fl in
  let t = ref (0.5 *. (!lo +. !hi)) and n = ref 0 in
  while !n < 100 && !hi -. !lo > 1e-14 *. (1. +. Float.abs !t) do
    incr n;
    let f = cubic c3 c2 c1 c0 !t in
    if f = 0. then (lo := !t; hi := !t)
    else begin
      if (f < 0.) = (!fl < 0.) then (lo := !t; fl := f) else hi := !t;
      let df = ((((3. *. c3) *. !t) +. (2. *. c2)) *. !t) +. c1 in
      let tn = if df <> 0. then !t -. (f /. df) else nan in
      t := if tn > !lo && tn < !hi then tn else 0.5 *. (!lo +. !hi)
    end
  done;
  !t

let[@inline] cubic_roots_in (found : Float.Array.t) c3 c2 c1 c0 lo hi =
  (* leading terms dropped as [first_root_in] drops them *)
  let a0 = Float.abs c0 and a1 = Float.abs c1 and a2 = Float.abs c2 in
  let n3 = not (Float.abs c3 <= 1e-16 *. ((a2 *. p1) +. (a1 *. p2) +. (a0 *. p3))) in
  let n2 = n3 || not (a2 <= 1e-16 *. ((a1 *. p1) +. (a0 *. p2))) in
  let n1 = n2 || not (a1 <= 1e-16 *. (a0 *. p1)) in
  if not n1 then 0
  else begin
    let c3 = if n3 then c3 else 0. and c2 = if n2 then c2 else 0. in
    (* Cauchy's bound, as there *)
    let lead = if n3 then c3 else if n2 then c2 else c1 in
    let b = mag_max 0. (Float.abs (c0 /. lead)) in
    let b = if n2 then mag_max b (Float.abs (c1 /. lead)) else b in
    let b = if n3 then mag_max b (Float.abs (c2 /. lead)) else b in
    let cap = 1. +. b in
    let cap = if reach < cap then reach else cap in
    let top = if cap < hi || cap <> cap then cap else hi in
    let from = lo -. 1e-12 in
    let start = if -.cap > from then -.cap else from in
    if not (start < top) then 0
    else if not n2 then begin
      (* a line: its root, strictly inside, as there *)
      let t = -.c0 /. c1 in
      if t > start && t < top && t >= lo then (Float.Array.unsafe_set found 0 t; 1) else 0
    end
    else begin
      (* the critical points: a quadratic's as there, a cubic's where
         its derivative qa s^2 + qb s + c1 is zero, without
         cancellation (none: nan) *)
      let qa = 3. *. c3 and qb = 2. *. c2 in
      let disc = (qb *. qb) -. (4. *. qa *. c1) in
      let q = -0.5 *. (if qb < 0. then qb -. Float.sqrt disc else qb +. Float.sqrt disc) in
      let ra = if not n3 then -.c1 /. qb else if disc < 0. then nan else if q = 0. then 0. else q /. qa in
      let rb = if not n3 then ra else if disc < 0. then nan else if q = 0. then 0. else c1 /. q in
      (* those inside (start, top), in order: [nc] of them, [s0] then
         [s1] *)
      let u = if rb < ra then rb else ra and v = if rb < ra then ra else rb in
      let in0 = u > start && u < top and in1 = v > start && v < top && v > u in
      let nc = (if in0 then 1 else 0) + if in1 then 1 else 0 in
      let s0 = if in0 then u else v and s1 = v in
      (* the pieces between [start], the critical points and [top]: a
         root where the ends differ in sign (or at a critical point);
         one within 1e-12 past the last is that one, and one below [lo]
         is passed over *)
      let count = ref 0 and from = ref from in
      let prev = ref start and fp = ref (cubic c3 c2 c1 c0 start) in
      for i = 0 to nc do
        let c = if i = nc then top else if i = 0 then s0 else s1 in
        let fc = cubic c3 c2 c1 c0 c in
        let r =
          if fc = 0. && i < nc then c
          else if !fp <> 0. && (!fp < 0.) <> (fc < 0.) then cubic_between c3 c2 c1 c0 !prev c !fp
          else nan
        in
        if r >= !from then begin
          if r >= lo then begin
            Float.Array.unsafe_set found !count r;
            incr count
          end;
          let past = r +. (1e-12 *. (1. +. Float.abs r)) and on = !from +. 1e-12 in
          from := if past > on then past else on
        end;
        prev := c;
        fp := fc
      done;
      !count
    end
  end

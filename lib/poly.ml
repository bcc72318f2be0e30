let newton3 a b c d t =
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

let eval a b c d e t = ((((((a *. t) +. b) *. t) +. c) *. t) +. d) *. t +. e
let deriv a b c d t = ((((4. *. a *. t) +. (3. *. b)) *. t) +. (2. *. c)) *. t +. d

(* A root of the polynomial in [lo, hi] where fl and fh have opposite
   signs: Newton steps kept inside the shrinking bracket, bisection when a
   step leaves it. *)
let bracketed a b c d e lo hi fl =
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

let first_quartic_root a b c d e lo hi =
  if not (hi > lo) then infinity
  else
    let crit = cubic_roots (4. *. a) (3. *. b) (2. *. c) d in
    let pts = Array.append [| lo |] (Array.append (Array.of_list (List.filter (fun x -> x > lo && x < hi) (Array.to_list crit))) [| hi |]) in
    let result = ref infinity in
    let i = ref 0 in
    let n = Array.length pts in
    while !result = infinity && !i < n - 1 do
      let p = pts.(!i) and q = pts.(!i + 1) in
      let fp = eval a b c d e p and fq = eval a b c d e q in
      if fq = 0. && q < hi then result := q
      else if (fp < 0.) <> (fq < 0.) && fp <> 0. then begin
        let t = bracketed a b c d e p q fp in
        if t > lo && t < hi then result := t
      end;
      incr i
    done;
    !result

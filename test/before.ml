(* The code the faster expansion along a ray (Algebraic) and search for a
   polynomial's first root (Poly) replaced, kept as the reference they
   must match to the bit (test_algebraic, test_poly). *)

let[@inline] g a i = Float.Array.unsafe_get a i
let reach = 1e7

let horner d base deg t =
  let acc = ref (g d (base + deg)) in
  for m = deg - 1 downto 0 do
    acc := (!acc *. t) +. g d (base + m)
  done;
  !acc

let root_between d w k deg lo hi fl =
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

let below (eqn : Float.Array.t) m =
  let s = ref 0. and p = ref 1. in
  for i = m - 1 downto 0 do
    p := !p /. reach;
    s := !s +. (Float.abs (g eqn i) *. !p)
  done;
  !s

(* every critical point of every level, then the first root: [None]
   for no root *)
let first_root_in (eqn : Float.Array.t) degree lo hi =
  let n = ref degree in
  while !n > 0 && Float.abs (g eqn !n) <= 1e-16 *. below eqn !n do decr n done;
  let n = !n in
  if n = 0 then None
  else begin
    let lead = g eqn n in
    let bound = ref 0. in
    for m = 0 to n - 1 do
      bound := Float.max !bound (Float.abs (g eqn m /. lead))
    done;
    (* every root within Cauchy's bound: the window clipped to it (not
       to minus its top, which dropped roots below -hi when hi < cap) *)
    let cap = Float.min reach (1. +. !bound) in
    let hi = Float.min hi cap in
    let lo = Float.max lo (-.cap) in
    if not (lo < hi) then None
    else begin
      let w = n + 1 in
      let d = Float.Array.make (w * w) 0. and r = Float.Array.make (w * w) 0. and nr = Array.make w 0 in
      for m = 0 to n do
        Float.Array.set d m (g eqn m)
      done;
      for k = 1 to n - 1 do
        for m = 0 to n - k do
          Float.Array.set d ((k * w) + m) (float (m + 1) *. g d (((k - 1) * w) + m + 1))
        done
      done;
      let base = (n - 1) * w in
      let t = -.g d base /. g d (base + 1) in
      if t > lo && t < hi then (Float.Array.set r base t; nr.(n - 1) <- 1);
      for lv = n - 2 downto 0 do
        let deg = n - lv and crit = (lv + 1) * w and ncrit = nr.(lv + 1) in
        let count = ref 0 and prev = ref lo and fp = ref (horner d (lv * w) deg lo) and i = ref 0 in
        while !i <= ncrit && not (lv = 0 && !count > 0) do
          let c = if !i < ncrit then g r (crit + !i) else hi in
          let fc = horner d (lv * w) deg c in
          if fc = 0. && !i < ncrit then (Float.Array.set r ((lv * w) + !count) c; incr count)
          else if !fp <> 0. && (!fp < 0.) <> (fc < 0.) then begin
            Float.Array.set r ((lv * w) + !count) (root_between d w lv deg !prev c !fp);
            incr count
          end;
          prev := c;
          fp := fc;
          incr i
        done;
        nr.(lv) <- !count
      done;
      if nr.(0) > 0 then Some (g r 0) else None
    end
  end

(* the polynomial along q + t n, term by term: each term's three powers
   along the line multiplied out, skipping zeros *)
let along order (coef : float array) qx qy qz nx ny nz =
  let w = order + 1 in
  let powers q n =
    let p = Float.Array.make (w * w) 0. in
    Float.Array.set p 0 1.;
    for e = 1 to order do
      for m = 0 to e do
        let a = if m < e then q *. g p (((e - 1) * w) + m) else 0. in
        let b = if m > 0 then n *. g p (((e - 1) * w) + m - 1) else 0. in
        Float.Array.set p ((e * w) + m) (a +. b)
      done
    done;
    p
  in
  let px = powers qx nx and py = powers qy ny and pz = powers qz nz in
  let eqn = Float.Array.make w 0. and term = ref 0 in
  for i = order downto 0 do
    for j = order - i downto 0 do
      for k = order - i - j downto 0 do
        let c = coef.(!term) in
        incr term;
        if c <> 0. then
          for a = 0 to i do
            let ca = c *. g px ((i * w) + a) in
            if ca <> 0. then
              for b = 0 to j do
                let cb = ca *. g py ((j * w) + b) in
                if cb <> 0. then
                  for d = 0 to k do
                    Float.Array.set eqn (a + b + d) (g eqn (a + b + d) +. (cb *. g pz ((k * w) + d)))
                  done
              done
          done
      done
    done
  done;
  eqn

(* Algebraic.first_hit as it was *)
let first_hit order coef ox oy oz dx dy dz tmin =
  let dl = Float.sqrt ((dx *. dx) +. (dy *. dy) +. (dz *. dz)) in
  let nx = dx /. dl and ny = dy /. dl and nz = dz /. dl in
  let t0 = -.((ox *. nx) +. (oy *. ny) +. (oz *. nz)) in
  let qx = ox +. (t0 *. nx) and qy = oy +. (t0 *. ny) and qz = oz +. (t0 *. nz) in
  let eqn = along order coef qx qy qz nx ny nz in
  let lo = Float.max (tmin *. dl) 1e-4 -. t0 in
  match first_root_in eqn order lo infinity with
  | Some r ->
      let t = (r +. t0) /. dl in
      if t > tmin then t else infinity
  | None -> infinity

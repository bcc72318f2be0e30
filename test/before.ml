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
    let hi = Float.min hi (Float.min reach (1. +. !bound)) in
    let lo = Float.max lo (-.hi) in
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

(* Noise as it was before the gradient tables were indexed by the corner
   (kept as the reference the noise must match to the bit, test_noise):
   the permutation by the fixed shuffle, the gradient picked per corner by
   the hash's low four bits (the vector noise's second and third by its
   high four and by the permutation's entry at it), each read from three
   16-entry tables of Perlin's 12 edge gradients. *)
module Noise = struct
  let perm =
    let p = Array.init 256 Fun.id in
    let s = ref 0x2545F491 in
    let next () =
      let x = !s in
      let x = x lxor ((x lsl 13) land 0xFFFFFFFF) in
      let x = x lxor (x lsr 17) in
      let x = x lxor ((x lsl 5) land 0xFFFFFFFF) in
      s := x;
      x
    in
    for i = 255 downto 1 do
      let j = next () mod (i + 1) in
      let t = p.(i) in
      p.(i) <- p.(j);
      p.(j) <- t
    done;
    Array.init 512 (fun i -> p.(i land 255))

  let fade t = t *. t *. t *. ((t *. ((t *. 6.) -. 15.)) +. 10.)
  let lerp t a b = a +. (t *. (b -. a))

  let edge h x y z =
    let u = if h < 8 then x else y in
    let v = if h < 4 then y else if h = 12 || h = 14 then x else z in
    (if h land 1 = 0 then u else -.u) +. if h land 2 = 0 then v else -.v

  let gx = Float.Array.init 16 (fun h -> edge h 1. 0. 0.)
  let gy = Float.Array.init 16 (fun h -> edge h 0. 1. 0.)
  let gz = Float.Array.init 16 (fun h -> edge h 0. 0. 1.)

  let grad h x y z =
    let h = h land 15 in
    (Float.Array.get gx h *. x) +. (Float.Array.get gy h *. y) +. (Float.Array.get gz h *. z)

  let ifloor x =
    let i = int_of_float x in
    if float_of_int i > x then i - 1 else i

  let p i = perm.(i)

  let cell_noise u v w x y z x1 y1 z1 k0 k1 k2 k3 k4 k5 k6 k7 =
    lerp w
      (lerp v (lerp u (grad k0 x y z) (grad k1 x1 y z)) (lerp u (grad k2 x y1 z) (grad k3 x1 y1 z)))
      (lerp v (lerp u (grad k4 x y z1) (grad k5 x1 y z1)) (lerp u (grad k6 x y1 z1) (grad k7 x1 y1 z1)))

  (* the cell of (x, y, z): its offsets, fades and the eight corner hashes *)
  let cell x y z =
    let ix = ifloor x and iy = ifloor y and iz = ifloor z in
    let xi = ix land 255 and yi = iy land 255 and zi = iz land 255 in
    let x = x -. float_of_int ix and y = y -. float_of_int iy and z = z -. float_of_int iz in
    let a = p xi + yi and b = p (xi + 1) + yi in
    let aa = p a + zi and ab = p (a + 1) + zi in
    let ba = p b + zi and bb = p (b + 1) + zi in
    ((x, y, z), [| p aa; p ba; p ab; p bb; p (aa + 1); p (ba + 1); p (ab + 1); p (bb + 1) |])

  let over (x, y, z) h f =
    cell_noise (fade x) (fade y) (fade z) x y z (x -. 1.) (y -. 1.) (z -. 1.) (f h.(0)) (f h.(1)) (f h.(2))
      (f h.(3)) (f h.(4)) (f h.(5)) (f h.(6)) (f h.(7))

  let snoise3 x y z =
    let q, h = cell x y z in
    over q h Fun.id

  let noise3 x y z = Float.min 1. (Float.max 0. (0.5 +. (0.5 *. snoise3 x y z)))

  let dnoise3 x y z =
    let q, h = cell x y z in
    (over q h Fun.id, over q h (fun h -> h lsr 4), over q h p)

  let turbulence ~octaves ~omega ~lambda (px, py, pz) =
    let ax = ref 0. and ay = ref 0. and az = ref 0. and amp = ref 1. and freq = ref 1. in
    for _ = 1 to Int.max 1 octaves do
      let f = !freq and a = !amp in
      let dx, dy, dz = dnoise3 (f *. px) (f *. py) (f *. pz) in
      ax := !ax +. (a *. dx);
      ay := !ay +. (a *. dy);
      az := !az +. (a *. dz);
      amp := !amp *. omega;
      freq := !freq *. lambda
    done;
    (!ax, !ay, !az)

  let fractal3 octaves x y z =
    let acc = ref 0. and f = ref 1. in
    for _ = 1 to Int.max 1 octaves do
      let k = !f in
      acc := !acc +. (Float.abs (snoise3 (k *. x) (k *. y) (k *. z)) /. k);
      f := k *. 2.
    done;
    !acc
end

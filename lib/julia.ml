(* Quaternion and hypercomplex Julia sets (see julia.mli). A quaternion
   is (a, v) with v = (b, c, d); q^2 = (a^2 - |v|^2, 2 a v), q^3 = (a^3 -
   3 a |v|^2, (3 a^2 - |v|^2) v). A hypercomplex number a + b i + c j + d k
   has i^2 = j^2 = -1, k^2 = 1 and commutes (POV-Ray's algebra):
   q^2 = (a^2 + d^2 - b^2 - c^2, 2 (a b - c d), 2 (a c - b d),
   2 (a d + b c)). *)

type t = {
  ca : float;
  cb : float;
  cc : float;
  cd : float;
  cube : bool;
  hyper : bool;
  n : int;
  step : float;
  r2 : float;  (** the bounding sphere's squared radius *)
  bail : float;  (** |q|^2 past which a point escapes *)
  r : float;
}

let tolerance = 1e-7

let make ~c ~hypercomplex ~cube ~max_iteration ~precision =
  if Array.length c <> 4 then Error "a julia_fractal's parameter is a 4-vector"
  else if max_iteration < 1 then Error "a julia_fractal needs max_iteration of at least 1"
  else if not (precision > 0.) then Error "a julia_fractal's precision must be positive"
  else if hypercomplex && cube then Error "a hypercomplex julia_fractal takes sqr only (cube is not supported by camlray)"
  else
    (* POV-Ray's bounding sphere: radius 1 + |c| (at most 2) for a
       quaternion set, 4 for a hypercomplex one; points escape past it
       (past |q| = 4 for a hypercomplex one) *)
    let r =
      if hypercomplex then 4.
      else
        Float.min 2.
          (1. +. Float.sqrt ((c.(0) *. c.(0)) +. (c.(1) *. c.(1)) +. (c.(2) *. c.(2)) +. (c.(3) *. c.(3))) +. 1e-7)
    in
    Ok { ca = c.(0); cb = c.(1); cc = c.(2); cd = c.(3); cube; hyper = hypercomplex; n = max_iteration; step = 1. /. precision;
         r2 = r *. r; bail = (if hypercomplex then 16. else (r *. r) +. 1e-7); r }

let bounds t = (Vec3.make (-.t.r) (-.t.r) (-.t.r), Vec3.make t.r t.r t.r)

let[@inline] unit_into (p : Vec3.m) (out : Vec3.m) gx gy gz =
  let l = Float.sqrt ((gx *. gx) +. (gy *. gy) +. (gz *. gz)) in
  if l > 0. && Float.is_finite l then Vec3.set out (gx /. l) (gy /. l) (gz /. l)
  else Vec3.set out p.mx p.my p.mz

(* Hypercomplex: the derivative of q_n = q_(n-1)^2 + c is 2^n times the
   product q_0 q_1 ... q_(n-1) (the algebra commutes), so the gradient of
   |q_n|^2 / 2 in x, y, z is q_n read through that product (POV-Ray's
   normal, scale aside). *)
let hyper_normal_into t (p : Vec3.m) (out : Vec3.m) =
  let a = ref p.mx and b = ref p.my and c = ref p.mz and d = ref 0. in
  let pa = ref 1. and pb = ref 0. and pc = ref 0. and pd = ref 0. in
  for _ = 1 to t.n do
    let a0 = !a and b0 = !b and c0 = !c and d0 = !d in
    let xa = !pa and xb = !pb and xc = !pc and xd = !pd in
    (* product := q * product *)
    pa := (a0 *. xa) -. (b0 *. xb) -. (c0 *. xc) +. (d0 *. xd);
    pb := (b0 *. xa) +. (a0 *. xb) -. (d0 *. xc) -. (c0 *. xd);
    pc := (c0 *. xa) -. (d0 *. xb) +. (a0 *. xc) -. (b0 *. xd);
    pd := (d0 *. xa) +. (c0 *. xb) +. (b0 *. xc) +. (a0 *. xd);
    a := (a0 *. a0) +. (d0 *. d0) -. (b0 *. b0) -. (c0 *. c0) +. t.ca;
    b := (2. *. ((a0 *. b0) -. (c0 *. d0))) +. t.cb;
    c := (2. *. ((a0 *. c0) -. (b0 *. d0))) +. t.cc;
    d := (2. *. ((a0 *. d0) +. (b0 *. c0))) +. t.cd
  done;
  let x = !pa and y = !pb and z = !pc and w = !pd in
  let n1 = !a and n2 = !b and n3 = !c and n4 = !d in
  unit_into p out
    ((x *. n1) +. (y *. n2) +. (z *. n3) +. (w *. n4))
    ((-.y *. n1) +. (x *. n2) -. (w *. n3) +. (z *. n4))
    ((-.z *. n1) -. (w *. n2) +. (x *. n3) +. (y *. n4))

(* A hypercomplex point's iteration, as POV-Ray walks a ray: [neg_infinity]
   when the point is inside; otherwise how far to step along the unit
   direction u. Where q_i escapes (|q_i|^2 = f > 16) the step is f / s,
   s = -2 g.u with g the gradient of |q_i|^2 / 2 (scaled by 2^i, as
   POV-Ray has it), when that lies between [step] and 30 [step] and the
   ray heads down the gradient; [step] otherwise. *)
let[@inline] hyper_probe t x y z ux uy uz =
  let a = ref x and b = ref y and c = ref z and d = ref 0. in
  (* q_0 ... q_(i-2) (q_0 while i <= 2, as POV-Ray has it), and 2^(i-1) *)
  let pa = ref x and pb = ref y and pc = ref z and pd = ref 0. and pow = ref 1. in
  let result = ref neg_infinity and i = ref 1 in
  while !i <= t.n do
    let a0 = !a and b0 = !b and c0 = !c and d0 = !d in
    let f = (a0 *. a0) +. (b0 *. b0) +. (c0 *. c0) +. (d0 *. d0) in
    if f > t.bail then begin
      let x = !pa and y = !pb and z = !pc and w = !pd in
      let n1 = !pow *. a0 and n2 = !pow *. b0 and n3 = !pow *. c0 and n4 = !pow *. d0 in
      let gx = (x *. n1) +. (y *. n2) +. (z *. n3) +. (w *. n4)
      and gy = (-.y *. n1) +. (x *. n2) -. (w *. n3) +. (z *. n4)
      and gz = (-.z *. n1) -. (w *. n2) +. (x *. n3) +. (y *. n4) in
      let s = (gx *. ux) +. (gy *. uy) +. (gz *. uz) in
      result := t.step;
      if s < -1e-8 then begin
        let s = -2. *. s in
        if f > t.step *. s && f < 30. *. t.step *. s then result := f /. s
      end;
      i := t.n + 1
    end
    else begin
      if !i > 1 then begin
        let xa = !pa and xb = !pb and xc = !pc and xd = !pd in
        pa := (a0 *. xa) -. (b0 *. xb) -. (c0 *. xc) +. (d0 *. xd);
        pb := (b0 *. xa) +. (a0 *. xb) -. (d0 *. xc) -. (c0 *. xd);
        pc := (c0 *. xa) -. (d0 *. xb) +. (a0 *. xc) -. (b0 *. xd);
        pd := (d0 *. xa) +. (c0 *. xb) +. (b0 *. xc) +. (a0 *. xd)
      end;
      pow := 2. *. !pow;
      a := (a0 *. a0) +. (d0 *. d0) -. (b0 *. b0) -. (c0 *. c0) +. t.ca;
      b := (2. *. ((a0 *. b0) -. (c0 *. d0))) +. t.cb;
      c := (2. *. ((a0 *. c0) -. (b0 *. d0))) +. t.cc;
      d := (2. *. ((a0 *. d0) +. (b0 *. c0))) +. t.cd;
      incr i
    end
  done;
  !result

(* The same for a quaternion point: where q_i escapes (|q_i|^2 = f), the
   step is k^-(i+1) sqrt (f / |q_0 ... q_i|^2) ln f (k = 2 for sqr, 3 for
   cube: POV-Ray's distance estimate, a lower bound of the distance to
   the set). *)
let[@inline] quaternion_probe t x y z =
  let a = ref x and b = ref y and c = ref z and d = ref 0. in
  let norms = ref 1. and pow = ref (if t.cube then 1. /. 3. else 0.5) in
  let result = ref neg_infinity and i = ref 1 in
  while !i <= t.n do
    let a0 = !a and vv = (!b *. !b) +. (!c *. !c) +. (!d *. !d) in
    let f = (a0 *. a0) +. vv in
    if f > t.bail then begin
      result := !pow *. Float.sqrt (f /. (!norms *. f)) *. Float.log f;
      i := t.n + 1
    end
    else begin
      norms := !norms *. f;
      pow := if t.cube then !pow /. 3. else !pow /. 2.;
      if t.cube then begin
        let s = (3. *. a0 *. a0) -. vv in
        a := (a0 *. a0 *. a0) -. (3. *. a0 *. vv) +. t.ca;
        b := (s *. !b) +. t.cb;
        c := (s *. !c) +. t.cc;
        d := (s *. !d) +. t.cd
      end
      else begin
        let s = 2. *. a0 in
        a := (a0 *. a0) -. vv +. t.ca;
        b := (s *. !b) +. t.cb;
        c := (s *. !c) +. t.cc;
        d := (s *. !d) +. t.cd
      end;
      incr i
    end
  done;
  !result

let[@inline] probe t x y z ux uy uz = if t.hyper then hyper_probe t x y z ux uy uz else quaternion_probe t x y z

(* bounded: q_0 ... q_(n-1) within the escape radius (POV-Ray's test) *)
let[@inline] inside t x y z =
  if not t.hyper then quaternion_probe t x y z = neg_infinity
  else begin
    let a = ref x and b = ref y and c = ref z and d = ref 0. in
    let ok = ref ((x *. x) +. (y *. y) +. (z *. z) <= t.bail) and i = ref 1 in
    while !ok && !i < t.n do
      let a0 = !a and b0 = !b and c0 = !c and d0 = !d in
      a := (a0 *. a0) +. (d0 *. d0) -. (b0 *. b0) -. (c0 *. c0) +. t.ca;
      b := (2. *. ((a0 *. b0) -. (c0 *. d0))) +. t.cb;
      c := (2. *. ((a0 *. c0) -. (b0 *. d0))) +. t.cc;
      d := (2. *. ((a0 *. d0) +. (b0 *. c0))) +. t.cd;
      if (!a *. !a) +. (!b *. !b) +. (!c *. !c) +. (!d *. !d) > t.bail then ok := false;
      incr i
    done;
    !ok
  end

(* POV-Ray's walk: from where the ray enters the bounding sphere, steps
   of [probe]'s length (at least [step]);
   a change between inside and outside is halved down to [tolerance] and
   the hit put on the inside. *)
let hit_s t (r : Ray.scratch) tmin (h : Hit.t) =
  let len = Float.sqrt ((r.dx *. r.dx) +. (r.dy *. r.dy) +. (r.dz *. r.dz)) in
  if len = 0. then false
  else begin
    let ux = r.dx /. len and uy = r.dy /. len and uz = r.dz /. len in
    let b = (r.ox *. ux) +. (r.oy *. uy) +. (r.oz *. uz) in
    let c = (r.ox *. r.ox) +. (r.oy *. r.oy) +. (r.oz *. r.oz) -. t.r2 in
    let disc = (b *. b) -. c in
    if disc < 0. then false
    else begin
      let sq = Float.sqrt disc in
      let smax = -.b +. sq in
      if smax < tolerance then false
      else begin
        let lo = tmin *. len and hi = h.t *. len in
        let depth = ref (Float.max (-.b -. sq) tolerance) in
        let pr = ref (probe t (r.ox +. (!depth *. ux)) (r.oy +. (!depth *. uy)) (r.oz +. (!depth *. uz)) ux uy uz) in
        if !pr = neg_infinity then begin
          depth := !depth +. (2. *. tolerance);
          pr := probe t (r.ox +. (!depth *. ux)) (r.oy +. (!depth *. uy)) (r.oz +. (!depth *. uz)) ux uy uz
        end;
        let cur = ref (!pr = neg_infinity) in
        let dist = ref (if !cur then t.step else !pr) in
        (* [ip]: the last point on the current side, [next] the probe ahead *)
        let next = ref !depth in
        let found = ref false and over = ref (!depth > smax) in
        while (not !found) && not !over do
          (* step until the side changes *)
          let crossed = ref false and ip = ref !next and next_dist = ref 0. in
          while (not !crossed) && not !over do
            if !dist < t.step then dist := t.step;
            if !next +. !dist > smax then over := true
            else begin
              ip := !next;
              next := !next +. !dist;
              let p = probe t (r.ox +. (!next *. ux)) (r.oy +. (!next *. uy)) (r.oz +. (!next *. uz)) ux uy uz in
              if (p = neg_infinity) <> !cur then begin
                crossed := true;
                next_dist := if p = neg_infinity then t.step else p
              end
              else dist := if p = neg_infinity then t.step else p
            end
          done;
          if !crossed then begin
            (* halve [dist] from [ip] towards [next] *)
            let at = ref !ip and dd = ref !dist in
            while !dd > tolerance do
              dd := 0.5 *. !dd;
              let m = !at +. !dd in
              if inside t (r.ox +. (m *. ux)) (r.oy +. (m *. uy)) (r.oz +. (m *. uz)) = !cur then at := m
            done;
            (* the inside side of the crossing *)
            let s = if !cur then !at else !at +. !dd in
            if s > lo && s < hi then begin
              let tt = s /. len in
              if tt > h.floor then begin
                h.t <- tt;
                h.u <- 0.;
                h.v <- 0.;
                h.id <- 0.;
                found := true
              end
            end;
            cur := not !cur;
            dist := !next_dist
          end
        done;
        !found
      end
    end
  end


(* the three derivative columns of the quaternion normal, per domain *)
let columns_key = Scratch.key (fun () -> Float.Array.make 12 0.)

(* column k (4 floats from [k]) of d q_(i+1) / d(x, y, z), from q_i =
   (a, v) and column k of d q_i: d(q^2) = 2 (a da - v.dv, a dv + da v);
   d(q^3) = (3 a^2 da - 3 da |v|^2 - 6 a v.dv, (6 a da - 2 v.dv) v + s dv)
   with s = 3 a^2 - |v|^2 *)
let[@inline] column cube m k a0 b0 c0 d0 vv =
  let da = Float.Array.unsafe_get m k and db = Float.Array.unsafe_get m (k + 1)
  and dc = Float.Array.unsafe_get m (k + 2) and dd = Float.Array.unsafe_get m (k + 3) in
  let vdu = (b0 *. db) +. (c0 *. dc) +. (d0 *. dd) in
  if cube then begin
    let s = (3. *. a0 *. a0) -. vv and kk = (6. *. a0 *. da) -. (2. *. vdu) in
    Float.Array.unsafe_set m k ((3. *. a0 *. a0 *. da) -. (3. *. da *. vv) -. (6. *. a0 *. vdu));
    Float.Array.unsafe_set m (k + 1) ((kk *. b0) +. (s *. db));
    Float.Array.unsafe_set m (k + 2) ((kk *. c0) +. (s *. dc));
    Float.Array.unsafe_set m (k + 3) ((kk *. d0) +. (s *. dd))
  end
  else begin
    Float.Array.unsafe_set m k (2. *. ((a0 *. da) -. vdu));
    Float.Array.unsafe_set m (k + 1) (2. *. ((a0 *. db) +. (da *. b0)));
    Float.Array.unsafe_set m (k + 2) (2. *. ((a0 *. dc) +. (da *. c0)));
    Float.Array.unsafe_set m (k + 3) (2. *. ((a0 *. dd) +. (da *. d0)))
  end

(* the gradient of |q_n|^2 in x, y, z: q and its three derivative
   columns carried through the steps *)
let quaternion_normal_into t (p : Vec3.m) (out : Vec3.m) =
  let m = Scratch.get columns_key in
  Float.Array.fill m 0 12 0.;
  Float.Array.unsafe_set m 0 1.;
  Float.Array.unsafe_set m 5 1.;
  Float.Array.unsafe_set m 10 1.;
  let a = ref p.mx and b = ref p.my and c = ref p.mz and d = ref 0. in
  for _ = 1 to t.n do
    let a0 = !a and b0 = !b and c0 = !c and d0 = !d in
    let vv = (b0 *. b0) +. (c0 *. c0) +. (d0 *. d0) in
    column t.cube m 0 a0 b0 c0 d0 vv;
    column t.cube m 4 a0 b0 c0 d0 vv;
    column t.cube m 8 a0 b0 c0 d0 vv;
    if t.cube then begin
      let s = (3. *. a0 *. a0) -. vv in
      a := (a0 *. a0 *. a0) -. (3. *. a0 *. vv) +. t.ca;
      b := (s *. b0) +. t.cb;
      c := (s *. c0) +. t.cc;
      d := (s *. d0) +. t.cd
    end
    else begin
      a := (a0 *. a0) -. vv +. t.ca;
      b := (2. *. a0 *. b0) +. t.cb;
      c := (2. *. a0 *. c0) +. t.cc;
      d := (2. *. a0 *. d0) +. t.cd
    end
  done;
  let a = !a and b = !b and c = !c and d = !d in
  unit_into p out
    ((a *. Float.Array.unsafe_get m 0) +. (b *. Float.Array.unsafe_get m 1) +. (c *. Float.Array.unsafe_get m 2) +. (d *. Float.Array.unsafe_get m 3))
    ((a *. Float.Array.unsafe_get m 4) +. (b *. Float.Array.unsafe_get m 5) +. (c *. Float.Array.unsafe_get m 6) +. (d *. Float.Array.unsafe_get m 7))
    ((a *. Float.Array.unsafe_get m 8) +. (b *. Float.Array.unsafe_get m 9) +. (c *. Float.Array.unsafe_get m 10) +. (d *. Float.Array.unsafe_get m 11))

let normal_into t p out = if t.hyper then hyper_normal_into t p out else quaternion_normal_into t p out

(* Quaternion Julia sets (see julia.mli). A quaternion is (a, v) with v
   = (b, c, d); q^2 = (a^2 - |v|^2, 2 a v), q^3 = (a^3 - 3 a |v|^2,
   (3 a^2 - |v|^2) v). *)

type t = { ca : float; cb : float; cc : float; cd : float; cube : bool; n : int; step : float; r2 : float; r : float }

let tolerance = 1e-7

let make ~c ~cube ~max_iteration ~precision =
  if Array.length c <> 4 then Error "a julia_fractal's parameter is a 4-vector"
  else if max_iteration < 1 then Error "a julia_fractal needs max_iteration of at least 1"
  else if not (precision > 0.) then Error "a julia_fractal's precision must be positive"
  else
    let r = 1. +. Float.sqrt ((c.(0) *. c.(0)) +. (c.(1) *. c.(1)) +. (c.(2) *. c.(2)) +. (c.(3) *. c.(3))) in
    Ok { ca = c.(0); cb = c.(1); cc = c.(2); cd = c.(3); cube; n = max_iteration; step = 1. /. precision;
         r2 = r *. r; r }

let bounds t = (Vec3.make (-.t.r) (-.t.r) (-.t.r), Vec3.make t.r t.r t.r)

(* bounded for n - 1 steps *)
let inside t x y z =
  let a = ref x and b = ref y and c = ref z and d = ref 0. in
  let ok = ref true and i = ref 1 in
  while !ok && !i < t.n do
    let a0 = !a and vv = (!b *. !b) +. (!c *. !c) +. (!d *. !d) in
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
    if (!a *. !a) +. (!b *. !b) +. (!c *. !c) +. (!d *. !d) > t.r2 then ok := false;
    incr i
  done;
  !ok

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
        let lo = tmin *. len in
        let hi = h.t *. len in
        let s = ref (Float.max (-.b -. sq) tolerance) in
        let ins_at s = inside t (r.ox +. (s *. ux)) (r.oy +. (s *. uy)) (r.oz +. (s *. uz)) in
        let cur = ref (ins_at !s) in
        if !cur then begin
          s := !s +. (2. *. tolerance);
          cur := ins_at !s
        end;
        let found = ref false in
        while (not !found) && !s < smax && !s < hi do
          let s2 = !s +. t.step in
          if s2 > smax then s := smax
          else begin
            let n2 = ins_at s2 in
            if n2 <> !cur then begin
              (* bisect: [a] on the old side, [b2] on the new *)
              let a = ref !s and b2 = ref s2 in
              while !b2 -. !a > tolerance do
                let m = 0.5 *. (!a +. !b2) in
                if ins_at m = n2 then b2 := m else a := m
              done;
              if !b2 > lo && !b2 < hi then begin
                let tt = !b2 /. len in
                if tt > h.floor then begin
                  h.t <- tt;
                  h.u <- 0.;
                  h.v <- 0.;
                  h.id <- 0.;
                  found := true
                end
              end;
              cur := n2
            end;
            s := s2
          end
        done;
        !found
      end
    end
  end

(* the gradient of |q_n|^2 in x, y, z: q and its three derivative
   columns carried through the steps *)
let normal_into t (p : Vec3.m) (out : Vec3.m) =
  let a = ref p.mx and b = ref p.my and c = ref p.mz and d = ref 0. in
  (* derivative columns: (da_k, db_k, dc_k, dd_k) for k = x, y, z *)
  let xa = ref 1. and xb = ref 0. and xc = ref 0. and xd = ref 0. in
  let ya = ref 0. and yb = ref 1. and yc = ref 0. and yd = ref 0. in
  let za = ref 0. and zb = ref 0. and zc = ref 1. and zd = ref 0. in
  for _ = 1 to t.n do
    let a0 = !a and b0 = !b and c0 = !c and d0 = !d in
    let vv = (b0 *. b0) +. (c0 *. c0) +. (d0 *. d0) in
    if t.cube then begin
      let s = (3. *. a0 *. a0) -. vv in
      (* d scalar = 3 a^2 da - 3 da |v|^2 - 6 a (v.dv); d vector = (6 a da - 2 v.dv) v + s dv *)
      let col qa qb qc qd =
        let vdu = (b0 *. !qb) +. (c0 *. !qc) +. (d0 *. !qd) in
        let da = !qa in
        let k = (6. *. a0 *. da) -. (2. *. vdu) in
        qa := (3. *. a0 *. a0 *. da) -. (3. *. da *. vv) -. (6. *. a0 *. vdu);
        qb := (k *. b0) +. (s *. !qb);
        qc := (k *. c0) +. (s *. !qc);
        qd := (k *. d0) +. (s *. !qd)
      in
      col xa xb xc xd;
      col ya yb yc yd;
      col za zb zc zd;
      a := (a0 *. a0 *. a0) -. (3. *. a0 *. vv) +. t.ca;
      b := (s *. b0) +. t.cb;
      c := (s *. c0) +. t.cc;
      d := (s *. d0) +. t.cd
    end
    else begin
      (* d(q^2) = 2 (a da - v.dv, a dv + da v) *)
      let col qa qb qc qd =
        let vdu = (b0 *. !qb) +. (c0 *. !qc) +. (d0 *. !qd) in
        let da = !qa in
        qa := 2. *. ((a0 *. da) -. vdu);
        qb := 2. *. ((a0 *. !qb) +. (da *. b0));
        qc := 2. *. ((a0 *. !qc) +. (da *. c0));
        qd := 2. *. ((a0 *. !qd) +. (da *. d0))
      in
      col xa xb xc xd;
      col ya yb yc yd;
      col za zb zc zd;
      a := (a0 *. a0) -. vv +. t.ca;
      b := (2. *. a0 *. b0) +. t.cb;
      c := (2. *. a0 *. c0) +. t.cc;
      d := (2. *. a0 *. d0) +. t.cd
    end
  done;
  let gx = (!a *. !xa) +. (!b *. !xb) +. (!c *. !xc) +. (!d *. !xd)
  and gy = (!a *. !ya) +. (!b *. !yb) +. (!c *. !yc) +. (!d *. !yd)
  and gz = (!a *. !za) +. (!b *. !zb) +. (!c *. !zc) +. (!d *. !zd) in
  let l = Float.sqrt ((gx *. gx) +. (gy *. gy) +. (gz *. gz)) in
  if l > 0. && Float.is_finite l then Vec3.set out (gx /. l) (gy /. l) (gz /. l)
  else Vec3.set out p.mx p.my p.mz

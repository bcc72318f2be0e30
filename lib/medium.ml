(* Participating media in Monte Carlo mode (see medium.mli). *)

let inv4pi = 0.25 /. Float.pi

(* all floats: stored flat, read and written without boxing *)
type nums = {
  mutable len : float;  (** the stretch's length *)
  mutable t : float;  (** where the medium scattered, along the stretch *)
  mutable maj : float;  (** the media's majorant *)
  mutable u : float;  (** the uniform left for choosing a scattering medium *)
  mutable tot : float;  (** the scattering media's summed weights at the point *)
  mutable pick : float;  (** the chosen one's weight *)
  mutable ph : float;  (** a phase function's value (per steradian) *)
  mutable pdf : float;  (** the density with which {!sample_phase} picks a direction *)
}

type t = {
  n : nums;
  q : Vec3.m;
  pig : Pigment.out;
  dens : Color.acc;
  ext : Color.acc;
  sca : Color.acc;
  emi : Color.acc;
  sci : Color.acc;
  mutable phase : Media.scattering;
  w : Color.acc;
  em : Color.acc;
  mutable scattered : bool;
  lw : Color.acc;  (** a shadow stretch's ratio-tracking weight *)
}

let none = Media.scattering 1 Color.black

let key =
  Scratch.key (fun () ->
      let c () = Color.acc 0. in
      { n = { len = 0.; t = 0.; maj = 0.; u = 0.; tot = 0.; pick = 0.; ph = 0.; pdf = 0. }; q = Vec3.m ();
        pig = Pigment.out (); dens = c (); ext = c (); sca = c (); emi = c (); sci = c (); phase = none; w = c ();
        em = c (); scattered = false; lw = c () })

let get () = Scratch.get key

(* {2 The media of a stretch} *)

let rec any_media = function [] -> false | (i : Interior.t) :: r -> i.media <> [] || any_media r
let present inside (air : Media.t list) = air <> [] || any_media inside
let rec media_constant = function [] -> true | (m : Media.t) :: r -> Media.constant m && media_constant r

let rec interiors_constant = function
  | [] -> true
  | (i : Interior.t) :: r -> media_constant i.media && interiors_constant r

let constant inside air = media_constant air && interiors_constant inside

(* the sum of the media's majorants into [md.n.maj] *)
let rec add_majorants md = function
  | [] -> ()
  | (m : Media.t) :: r ->
      md.n.maj <- md.n.maj +. Media.majorant m;
      add_majorants md r

let rec add_interior_majorants md = function
  | [] -> ()
  | (i : Interior.t) :: r ->
      add_majorants md i.media;
      add_interior_majorants md r

let majorant md inside air =
  md.n.maj <- 0.;
  add_interior_majorants md inside;
  add_majorants md air

(* medium [m]'s coefficients at [p] added to the point's; a scattering
   medium is chosen among those there in proportion to its mean
   scattering, with the one uniform [md.n.u] (rescaled after each
   decision, so that it stays uniform) *)
let add_medium md (m : Media.t) p =
  Media.add_extinction m p md.pig md.dens md.ext;
  (* [add_extinction] left the density in [dens] (as {!Volume} reads it) *)
  let c = Media.constant m in
  let dr = if c then 1. else md.dens.ar and dg = if c then 1. else md.dens.ag and db = if c then 1. else md.dens.ab in
  let e = md.emi in
  Color.acc_set e (e.ar +. (dr *. m.emission.r)) (e.ag +. (dg *. m.emission.g)) (e.ab +. (db *. m.emission.b));
  match m.scattering with
  | None -> ()
  | Some sc ->
      let sr = dr *. sc.color.r and sg = dg *. sc.color.g and sb = db *. sc.color.b in
      let s = md.sca in
      Color.acc_set s (s.ar +. sr) (s.ag +. sg) (s.ab +. sb);
      let wi = Float.abs sr +. Float.abs sg +. Float.abs sb in
      if wi > 0. then begin
        let n = md.n in
        n.tot <- n.tot +. wi;
        let p = wi /. n.tot in
        if n.u < p then begin
          n.u <- n.u /. p;
          n.pick <- wi;
          Color.acc_set md.sci sr sg sb;
          if md.phase != sc then md.phase <- sc
        end
        else n.u <- (n.u -. p) /. (1. -. p)
      end

let rec add_media md ms p =
  match ms with
  | [] -> ()
  | m :: r ->
      add_medium md m p;
      add_media md r p

let rec add_interiors md (l : Interior.t list) p =
  match l with
  | [] -> ()
  | i :: r ->
      add_media md i.media p;
      add_interiors md r p

(* every coefficient at [p] ([md.n.u] set by the caller) *)
let coefficients md inside air p =
  Color.acc_set md.ext 0. 0. 0.;
  Color.acc_set md.sca 0. 0. 0.;
  Color.acc_set md.emi 0. 0. 0.;
  md.n.tot <- 0.;
  add_interiors md inside p;
  add_media md air p

(* the extinction alone at [p], into [md.ext] *)
let rec add_ext md ms p =
  match ms with
  | [] -> ()
  | m :: r ->
      Media.add_extinction m p md.pig md.dens md.ext;
      add_ext md r p

let rec add_ext_interiors md (l : Interior.t list) p =
  match l with
  | [] -> ()
  | i :: r ->
      add_ext md i.media p;
      add_ext_interiors md r p

let extinction md inside air p =
  Color.acc_set md.ext 0. 0. 0.;
  add_ext_interiors md inside p;
  add_ext md air p

(* {2 Random numbers}

   Tracking draws as many numbers as it takes steps: they come from
   dimensions far above the path's own blocks ({!Path}), each stretch its
   own range. *)

let steps_max = 1 lsl 16
let track_dims = 1 lsl 40
let[@inline] track_dim ~depth = track_dims + (depth lsl 20)
let shadow_dims = 1 lsl 50
let[@inline] shadow_dim ~depth ~which ~cross = shadow_dims + (((((depth lsl 10) + which) lsl 6) + cross) lsl 18)

(* an exponential step of rate [rate] *)
let[@inline] step u rate = -.Float.log1p (-.u) /. rate

(* {2 Free flight along a path's stretch} *)

(* (1 - exp (-s l)) / s, the integral of the transmittance *)
let[@inline] through s l = if s = 0. then l else -.Float.expm1 (-.s *. l) /. s

(* After a tracking step: Russian roulette on a weight grown small (all
   channels under 0.1 in magnitude: kept with probability its size, by
   the sampler's number at [dim], and scaled up to 0.1), then the cap of
   [steps_max] steps a stretch; false when the walk ends here, its
   weight zeroed *)
let goes_on (w : Color.acc) sampler dim steps =
  let m = Float.max (Float.abs w.ar) (Float.max (Float.abs w.ag) (Float.abs w.ab)) in
  let alive =
    (not (m < 0.1))
    || Sampler.get sampler dim *. 0.1 < m
       && begin
         let f = 0.1 /. m in
         Color.acc_set w (f *. w.ar) (f *. w.ag) (f *. w.ab);
         true
       end
  in
  let alive = alive && steps < steps_max in
  if not alive then Color.acc_set w 0. 0. 0.;
  alive

let homogeneous md sampler dim inside air (o : Vec3.m) (thr : Color.acc) =
  let n = md.n in
  let l = n.len in
  n.u <- Sampler.get sampler (dim + 1);
  coefficients md inside air o;
  let x = md.ext and e = md.emi and s = md.sca in
  Color.acc_set md.em (e.ar *. through x.ar l) (e.ag *. through x.ag l) (e.ab *. through x.ab l);
  if Color.acc_is_black s then
    Color.acc_set md.w (Float.exp (-.x.ar *. l)) (Float.exp (-.x.ag *. l)) (Float.exp (-.x.ab *. l))
  else begin
    (* a channel chosen in proportion to the throughput, its
       exponential distance; the density is the mixture's *)
    let qr = Float.abs thr.ar and qg = Float.abs thr.ag and qb = Float.abs thr.ab in
    let qs = qr +. qg +. qb in
    let qr = if qs > 0. then qr /. qs else 1. /. 3.
    and qg = if qs > 0. then qg /. qs else 1. /. 3.
    and qb = if qs > 0. then qb /. qs else 1. /. 3. in
    let u = Sampler.get sampler dim in
    let t =
      if u < qr then step (u /. qr) x.ar
      else if u < qr +. qg then step ((u -. qr) /. qg) x.ag
      else step (Float.min 1. ((u -. qr -. qg) /. qb)) x.ab
    in
    if t < l then begin
      let tr = Float.exp (-.x.ar *. t) and tg = Float.exp (-.x.ag *. t) and tb = Float.exp (-.x.ab *. t) in
      let pdf = (qr *. x.ar *. tr) +. (qg *. x.ag *. tg) +. (qb *. x.ab *. tb) in
      let k = n.tot /. n.pick /. pdf and c = md.sci in
      Color.acc_set md.w (k *. c.ar *. tr) (k *. c.ag *. tg) (k *. c.ab *. tb);
      n.t <- t;
      md.scattered <- true
    end
    else begin
      let tr = Float.exp (-.x.ar *. l) and tg = Float.exp (-.x.ag *. l) and tb = Float.exp (-.x.ab *. l) in
      let p = (qr *. tr) +. (qg *. tg) +. (qb *. tb) in
      Color.acc_set md.w (tr /. p) (tg /. p) (tb /. p)
    end
  end

let looks = 8.

(* weighted delta tracking against the majorant (spectral tracking,
   Kutz et al. 2017, without absorption events): at each tentative
   collision the emission is scored, then the medium scatters or the
   collision is null, in proportion to the weighted scattering and null
   coefficients; a negative null coefficient (a density above its bound)
   stays unbiased *)
let tracking md sampler dim inside air (o : Vec3.m) (d : Vec3.m) =
  let n = md.n in
  let l = n.len in
  majorant md inside air;
  (* at least [looks] tentative collisions a stretch, on average: where
     the media emit more than they dim, the emission is read that often *)
  let maj = Float.max n.maj (looks /. l) in
  let w = md.w and em = md.em in
  Color.acc_set em 0. 0. 0.;
  Color.acc_set w 1. 1. 1.;
  if maj > 0. then begin
    let t = ref 0. and k = ref 0 and go = ref true in
    while !go do
      let b = dim + (4 * !k) in
      t := !t +. step (Sampler.get sampler b) maj;
      if !t >= l then go := false
      else begin
        let x = !t in
        Vec3.set md.q (o.mx +. (x *. d.mx)) (o.my +. (x *. d.my)) (o.mz +. (x *. d.mz));
        n.u <- Sampler.get sampler (b + 3);
        coefficients md inside air md.q;
        let e = md.emi in
        let ki = 1. /. maj in
        Color.acc_set em (em.ar +. (ki *. w.ar *. e.ar)) (em.ag +. (ki *. w.ag *. e.ag)) (em.ab +. (ki *. w.ab *. e.ab));
        let s = md.sca and xt = md.ext in
        let nr = maj -. xt.ar and ng = maj -. xt.ag and nb = maj -. xt.ab in
        let a = Float.abs (w.ar *. s.ar) +. Float.abs (w.ag *. s.ag) +. Float.abs (w.ab *. s.ab)
        and z = Float.abs (w.ar *. nr) +. Float.abs (w.ag *. ng) +. Float.abs (w.ab *. nb) in
        if a +. z <= 0. then begin
          Color.acc_set w 0. 0. 0.;
          go := false
        end
        else begin
          let ps = a /. (a +. z) in
          if Sampler.get sampler (b + 1) < ps then begin
            let c = md.sci and f = n.tot /. n.pick /. (maj *. ps) in
            Color.acc_set w (f *. w.ar *. c.ar) (f *. w.ag *. c.ag) (f *. w.ab *. c.ab);
            n.t <- x;
            md.scattered <- true;
            go := false
          end
          else begin
            let f = 1. /. (maj *. (1. -. ps)) in
            Color.acc_set w (f *. w.ar *. nr) (f *. w.ag *. ng) (f *. w.ab *. nb);
            incr k;
            if not (goes_on w sampler (b + 2) !k) then go := false
          end
        end
      end
    done
  end

let segment md sampler ~depth ~dim inside air (o : Vec3.m) (d : Vec3.m) (thr : Color.acc) =
  md.scattered <- false;
  if constant inside air then homogeneous md sampler dim inside air o thr
  else tracking md sampler (track_dim ~depth) inside air o d

(* {2 Transmittance along a shadow ray} *)

let transmittance md sampler dim inside air (o : Vec3.m) (d : Vec3.m) (out : Color.acc) =
  let l = md.n.len in
  if constant inside air then begin
    extinction md inside air o;
    let x = md.ext in
    Color.acc_set out (out.ar *. Float.exp (-.x.ar *. l)) (out.ag *. Float.exp (-.x.ag *. l))
      (out.ab *. Float.exp (-.x.ab *. l))
  end
  else begin
    (* ratio tracking *)
    majorant md inside air;
    let maj = md.n.maj in
    if maj > 0. then begin
      let w = md.lw in
      Color.acc_set w 1. 1. 1.;
      let t = ref 0. and k = ref 0 and go = ref true in
      while !go do
        let b = dim + (2 * !k) in
        t := !t +. step (Sampler.get sampler b) maj;
        if !t >= l then go := false
        else begin
          let x = !t in
          Vec3.set md.q (o.mx +. (x *. d.mx)) (o.my +. (x *. d.my)) (o.mz +. (x *. d.mz));
          extinction md inside air md.q;
          let xt = md.ext and f = 1. /. maj in
          Color.acc_set w (w.ar *. (1. -. (f *. xt.ar))) (w.ag *. (1. -. (f *. xt.ag))) (w.ab *. (1. -. (f *. xt.ab)));
          incr k;
          if not (goes_on w sampler (b + 1) !k) then go := false
        end
      done;
      Color.acc_set out (out.ar *. w.ar) (out.ag *. w.ag) (out.ab *. w.ab)
    end
  end

(* {2 Phase functions} *)

(* POV-Ray's phase functions average 1 over the sphere: divided by 4 pi,
   densities. Mie hazy and murky and Rayleigh are sampled from a table of
   their integral over the cosine (piecewise constant), isotropic and
   Henyey-Greenstein exactly. *)
let bins = 1024
let width = 2. /. float_of_int bins

let table kind =
  let sc = Media.scattering kind Color.black in
  let cdf = Float.Array.make (bins + 1) 0. in
  let sub = 16 in
  for k = 0 to bins - 1 do
    let lo = -1. +. (width *. float_of_int k) in
    let s = ref 0. in
    for j = 0 to sub - 1 do
      s := !s +. Media.phase sc (lo +. (width *. (float_of_int j +. 0.5) /. float_of_int sub))
    done;
    Float.Array.set cdf (k + 1) (Float.Array.get cdf k +. (!s *. width /. float_of_int sub))
  done;
  let total = Float.Array.get cdf bins in
  (Float.Array.map (fun v -> v /. total) cdf, 2. /. total)

let hazy, hazy_k = table 2
let murky, murky_k = table 3
let rayleigh, rayleigh_k = table 4
let cdf_of kind = if kind = 2 then hazy else if kind = 3 then murky else rayleigh

(* POV-Ray's Mie hazy, Mie murky and Rayleigh average 1.1533, 1.2468 and
   1.0658 over the sphere (its constants): scaled to 1, and to 1 / (4 pi)
   per steradian *)
let[@inline] scale kind =
  inv4pi *. if kind = 2 then hazy_k else if kind = 3 then murky_k else if kind = 4 then rayleigh_k else 1.
let tabled kind = kind = 2 || kind = 3 || kind = 4
let[@inline] hg (sc : Media.scattering) = sc.kind = 5 && Float.abs sc.eccentricity > 1e-4

(* the density of the table's cosine at [c], per steradian *)
let[@inline] table_pdf cdf c =
  let k = Int.max 0 (Int.min (bins - 1) (int_of_float ((c +. 1.) /. width))) in
  (Float.Array.get cdf (k + 1) -. Float.Array.get cdf k) /. width /. (2. *. Float.pi)

let[@inline] phase_at md (sc : Media.scattering) c =
  let n = md.n in
  n.ph <- Media.phase sc c *. scale sc.kind;
  n.pdf <-
    (if tabled sc.kind then table_pdf (cdf_of sc.kind) c else if hg sc then n.ph else inv4pi)

(* the largest [k] with [cdf.(k) <= u] *)
let find cdf u =
  let lo = ref 0 and hi = ref bins in
  while !hi - !lo > 1 do
    let m = (!lo + !hi) / 2 in
    if Float.Array.get cdf m <= u then lo := m else hi := m
  done;
  !lo

let[@inline] sample_phase md (sc : Media.scattering) (d : Vec3.m) u v (wi : Vec3.m) =
  let c =
    if tabled sc.kind then begin
      let cdf = cdf_of sc.kind in
      let k = find cdf u in
      let a = Float.Array.get cdf k and b = Float.Array.get cdf (k + 1) in
      let f = if b > a then (u -. a) /. (b -. a) else 0.5 in
      Float.min 1. (Float.max (-1.) (-1. +. (width *. (float_of_int k +. f))))
    end
    else if hg sc then begin
      let g = sc.eccentricity in
      let k = (1. -. (g *. g)) /. (1. -. g +. (2. *. g *. u)) in
      Float.min 1. (Float.max (-1.) ((1. +. (g *. g) -. (k *. k)) /. (2. *. g)))
    end
    else 1. -. (2. *. u)
  in
  Bsdf.around_into wi d.mx d.my d.mz c (2. *. Float.pi *. v);
  phase_at md sc c

(* Media along a ray in whitted mode (see volume.mli). A sample at a
   point holds six numbers: extinction, and emitted plus scattered
   light. *)

let slot = 6
let max_depth = 12

(* where along the ray the sample being read is, the interval being
   sampled and its split threshold (an all-float record: the floats are
   not boxed; passed as arguments they would be) *)
type at = {
  mutable x : float;
  mutable lo : float;
  mutable hi : float;
  mutable thr : float;
  mutable aa : float;
  mutable cos : float;  (** the cosine the phases are read at *)
  mutable phases : float;  (** their sum *)
}

type st = {
  buf : Float.Array.t;  (** samples: 0 and 1 a stretch's ends, 2 + k a middle at depth k *)
  r : Ray.scratch;  (** the ray, its direction unit *)
  p : Vec3.m;
  pig : Pigment.out;
  dens : Color.acc;
  ext : Color.acc;
  lit : Color.acc;  (** the light scattered at a sample *)
  sc : Color.acc;  (** the media's scattering there, summed *)
  mutable scatters : bool;  (** some medium of the sample scatters *)
  mutable count : int;  (** how many media the ray is in *)
  mutable starts : Interior.t list;  (** the interiors the ray runs in, where its shadow rays start *)
  sum : Color.acc;  (** a stretch's mean of the second triple *)
  sumx : Color.acc;  (** its mean extinction *)
  od : Color.acc;  (** the optical depth of the ray so far *)
  got : Color.acc;  (** the light gathered so far *)
  lit_spans : Lit.t;  (** the ray's lit and unlit stretches *)
  mutable lit_now : bool;  (** the interval sampled is lit *)
  at : at;
  stack : Float.Array.t;
      (** the stretches being split: at depth [d], floats [3d] to [3d + 2]
          are a stretch's ends and weight *)
}

let key =
  Scratch.key (fun () ->
      { buf = Float.Array.make (slot * (max_depth + 3)) 0.; r = Ray.scratch (); p = Vec3.m ();
        pig = Pigment.out (); dens = Color.acc 0.; ext = Color.acc 0.; lit = Color.acc 0.;
        sc = Color.acc 0.; scatters = false; count = 0; starts = [];
        sum = Color.acc 0.; sumx = Color.acc 0.; od = Color.acc 0.; got = Color.acc 0.;
        lit_spans = Lit.make (); lit_now = false;
        at = { x = 0.; lo = 0.; hi = 0.; thr = 0.; aa = 0.; cos = 0.; phases = 0. }; stack = Float.Array.make (3 * (max_depth + 2)) 0. })

(* the phases of all the media the ray is in at the cosine [a.cos],
   summed into [a.phases]; a medium that does not scatter counts as
   isotropic (POV-Ray's default type) *)
let rec phases (a : at) = function
  | [] -> ()
  | (i : Interior.t) :: r ->
      phases_of a i.media;
      phases a r

and phases_of a = function
  | [] -> ()
  | (m : Media.t) :: ms ->
      (match m.scattering with
      | Some sc -> a.phases <- a.phases +. Media.phase sc a.cos
      | None -> a.phases <- a.phases +. 1.);
      phases_of a ms

(* some medium of the interiors collects photons (POV-Ray's flag is
   that all of them say collect off) *)
let rec collecting = function
  | [] -> false
  | (i : Interior.t) :: r -> List.exists (fun (m : Media.t) -> m.collect) i.media || collecting r

let rec count = function [] -> 0 | (i : Interior.t) :: r -> List.length i.media + count r

(* the light of every light that lights the ray at [p] (media-interacting
   and not shadowless: see {!Lit.cut}), each weighted by the phase toward
   the eye, into [st.lit]. POV-Ray 3.7 (media.cpp's
   ComputeMediaScatteringAttenuation) weighs the media's summed
   scattering by the mean of all their phases, not each medium's by its
   own: so does this (measured: Mie hazy and Rayleigh media in one
   interior) *)
let in_scatter (s : Scene.t) st (inside : Interior.t list) (p : Vec3.m) =
  let lit = st.lit and r = st.r in
  Color.acc_set lit 0. 0. 0.;
  let w = Shadow.walk () in
  Shadow.starts_in w st.starts;
  (* with photons, refracting targets block the samples' shadow rays:
     their light comes as media photons (POV-Ray's rule, on the
     surfaces' map) *)
  Shadow.collects w
    (match s.settings.photons with
    | None -> false
    | Some { state = { map = Some m; _ }; _ } -> Photon.size m > 0 && collecting inside
    | Some _ -> false);
  let l = Shadow.toward w in
  let n = float_of_int st.count in
  for i = 0 to Array.length s.lights - 1 do
    let light = s.lights.(i) in
    (* POV-Ray reads a light only inside its lit part of the ray *)
    if Lit.lights st.lit_spans i st.at.x then begin
      Light.direction_into light p l;
      let att = Light.attenuation_m light p in
      if att > 0. then begin
        (* no tuple: the channels stay unboxed; a shadowless light
           never gets here *)
        Shadow.light s w light p;
        let a = Shadow.passed w in
        (* the light travels along -l, the eye is back along the ray *)
        st.at.cos <- (l.lx *. r.dx) +. (l.ly *. r.dy) +. (l.lz *. r.dz);
        st.at.phases <- 0.;
        phases st.at inside;
        let k = att *. (st.at.phases /. n) in
        Color.acc_set lit
          (lit.ar +. (k *. a.ar *. light.color.r))
          (lit.ag +. (k *. a.ag *. light.color.g))
          (lit.ab +. (k *. a.ab *. light.color.b))
      end
    end
  done

(* POV-Ray's media photons at [p] (media.cpp's ComputeMediaPhotons): the
   nearest of the media map (plain distance), each a light from where it
   came weighted by the media's mean phase, over the volume of the
   gather, into [st.lit] *)
let media_photons st inside (m : Photon.map) (p : Vec3.m) =
  let lit = st.lit and r = st.r in
  Color.acc_set lit 0. 0. 0.;
  let q = Photon.query () in
  Photon.gather_volume m q p;
  let cnt = Photon.found q in
  if cnt > 0 then begin
    let n = float_of_int st.count *. Photon.volume q in
    for j = 0 to cnt - 1 do
      let i = Photon.index q j in
      st.at.cos <-
        (Photon.direction m i 0 *. r.dx) +. (Photon.direction m i 1 *. r.dy) +. (Photon.direction m i 2 *. r.dz);
      st.at.phases <- 0.;
      phases st.at inside;
      let k = st.at.phases /. n in
      Color.acc_set lit
        (lit.ar +. (k *. Photon.flux m i 0))
        (lit.ag +. (k *. Photon.flux m i 1))
        (lit.ab +. (k *. Photon.flux m i 2))
    done
  end

(* The sample buffer and the stretch stack are read and written
   unchecked from here to [stretch]: slots 0 to max_depth + 2 of [slot]
   floats (a stretch at depth d, at most max_depth, samples its middle
   into slot 2 + d) and 3 floats a depth up to max_depth, both sized so
   at [key]. *)

(* [v] added to the sample buffer's [i]th float *)
let[@inline] bump b i v = Float.Array.unsafe_set b i (Float.Array.unsafe_get b i +. v)

(* medium [m]'s share of the sample at [p] (the ray's point), added to the
   buffer's slot at [o] *)
let medium st (m : Media.t) p o =
  let b = st.buf in
  Color.acc_set st.ext 0. 0. 0.;
  Media.add_extinction m p st.pig st.dens st.ext;
  (* [add_extinction] left the density in [dens]; no tuple: the channels
     stay unboxed *)
  let c = Media.constant m in
  let dr = if c then 1. else st.dens.ar and dg = if c then 1. else st.dens.ag and db = if c then 1. else st.dens.ab in
  bump b o st.ext.ar;
  bump b (o + 1) st.ext.ag;
  bump b (o + 2) st.ext.ab;
  bump b (o + 3) (dr *. m.emission.r);
  bump b (o + 4) (dg *. m.emission.g);
  bump b (o + 5) (db *. m.emission.b);
  match m.scattering with
  | None -> ()
  | Some sc ->
      st.scatters <- true;
      let t = st.sc in
      Color.acc_set t (t.ar +. (dr *. sc.color.r)) (t.ag +. (dg *. sc.color.g)) (t.ab +. (db *. sc.color.b))

(* every medium of the interiors, in order (loops, not closures: a
   sample is taken thousands of times a ray) *)
let rec media_of st (ms : Media.t list) p o =
  match ms with
  | [] -> ()
  | m :: rest ->
      medium st m p o;
      media_of st rest p o

let rec interiors st (inside : Interior.t list) p o =
  match inside with
  | [] -> ()
  | i :: rest ->
      media_of st i.media p o;
      interiors st rest p o

(* the sample at [st.at.x] along the ray into slot [k] *)
let sample s st (inside : Interior.t list) k =
  let r = st.r and p = st.p in
  let x = st.at.x in
  Vec3.set p (r.ox +. (x *. r.dx)) (r.oy +. (x *. r.dy)) (r.oz +. (x *. r.dz));
  let b = st.buf and o = k * slot in
  for j = 0 to slot - 1 do
    Float.Array.unsafe_set b (o + j) 0.
  done;
  Color.acc_set st.sc 0. 0. 0.;
  st.scatters <- false;
  interiors st inside p o;
  if st.scatters && st.lit_now then begin
    in_scatter s st inside p;
    let t = st.sc and lit = st.lit in
    bump b (o + 3) (t.ar *. lit.ar);
    bump b (o + 4) (t.ag *. lit.ag);
    bump b (o + 5) (t.ab *. lit.ab)
  end;
  (* media photons, lit stretch or not *)
  if st.scatters then
    match s.settings.photons with
    | Some { state = { media_map = Some m; _ }; _ } ->
        media_photons st inside m p;
        let t = st.sc and lit = st.lit in
        bump b (o + 3) (t.ar *. lit.ar);
        bump b (o + 4) (t.ag *. lit.ag);
        bump b (o + 5) (t.ab *. lit.ab)
    | _ -> ()

(* POV-Ray's test for splitting a stretch: the colours of two samples
   (emitted plus scattered light, over the whole interval: [thr] comes
   divided by the interval's length) differ by more than [thr], summed
   over the channels *)
let differ st ka kb thr =
  let b = st.buf and oa = ka * slot and ob = kb * slot in
  Float.abs (Float.Array.unsafe_get b (oa + 3) -. Float.Array.unsafe_get b (ob + 3))
  +. Float.abs (Float.Array.unsafe_get b (oa + 4) -. Float.Array.unsafe_get b (ob + 4))
  +. Float.abs (Float.Array.unsafe_get b (oa + 5) -. Float.Array.unsafe_get b (ob + 5))
  > thr

(* the samples in slots [ka], [kb], [kc] weighing [wa], [wb], [wc] added
   to [sumx] and [sum] *)
let[@inline] mix bf oa ob oc wa wb wc j =
  (wa *. Float.Array.unsafe_get bf (oa + j)) +. (wb *. Float.Array.unsafe_get bf (ob + j)) +. (wc *. Float.Array.unsafe_get bf (oc + j))

let add3 st ka kb kc wa wb wc =
  let bf = st.buf and oa = ka * slot and ob = kb * slot and oc = kc * slot in
  let sx = st.sumx and sm = st.sum in
  Color.acc_set sx
    (sx.ar +. mix bf oa ob oc wa wb wc 0)
    (sx.ag +. mix bf oa ob oc wa wb wc 1)
    (sx.ab +. mix bf oa ob oc wa wb wc 2);
  Color.acc_set sm
    (sm.ar +. mix bf oa ob oc wa wb wc 3)
    (sm.ag +. mix bf oa ob oc wa wb wc 4)
    (sm.ab +. mix bf oa ob oc wa wb wc 5)

(* a stretch [a, b] weighing [w], whose ends are in slots [ka], [kb], its
   middle read into slot 2 + depth; with [level] splits left, each half
   whose ends differ (see [differ]) is split again, as POV-Ray 3.7 does
   (images identical to its own on spotlight beams): a whole stretch
   counts its ends and middle alike, a half left whole counts its outer
   end twice as much as the middle (the middle's other share goes with
   the other half) *)
let[@inline] push st depth a b w =
  let f = st.stack and o = 3 * depth in
  Float.Array.unsafe_set f o a;
  Float.Array.unsafe_set f (o + 1) b;
  Float.Array.unsafe_set f (o + 2) w

(* the stretch at [depth] on [st.stack]; the threshold is [st.at.thr] *)
let rec stretch s st inside ka kb depth level =
  let f = st.stack and o = 3 * depth in
  let a = Float.Array.unsafe_get f o and b = Float.Array.unsafe_get f (o + 1) and w = Float.Array.unsafe_get f (o + 2) in
  let km = 2 + depth in
  st.at.x <- 0.5 *. (a +. b);
  sample s st inside km;
  if level <= 0 || depth >= max_depth then add3 st ka km kb (w /. 3.) (w /. 3.) (w /. 3.)
  else begin
    let m = 0.5 *. (a +. b) in
    if differ st ka km st.at.thr then begin
      push st (depth + 1) a m (0.5 *. w);
      stretch s st inside ka km (depth + 1) (level - 1)
    end
    else add3 st ka km kb (w /. 3.) (w /. 6.) 0.;
    if differ st km kb st.at.thr then begin
      push st (depth + 1) m b (0.5 *. w);
      stretch s st inside km kb (depth + 1) (level - 1)
    end
    else add3 st ka km kb 0. (w /. 6.) (w /. 3.)
  end

(* the media of the first interior that has any ([[]]: none has) *)
let rec first_media = function
  | [] -> []
  | (i : Interior.t) :: r -> ( match i.media with [] -> first_media r | ms -> ms)

(* POV-Ray samples with the settings of the medium with the most
   intervals, the first of them in its order: the interiors as the ray
   entered them (the list holds the last entered first), each one's media
   as written; [none] below every medium *)
let none = { Media.default with intervals = min_int }

let rec most_intervals = function
  | [] -> none
  | (i : Interior.t) :: older -> pick (most_intervals older) i.media

and pick best = function
  | [] -> best
  | (m : Media.t) :: ms -> pick (if m.intervals > best.intervals then m else best) ms

(* and the smallest aa_threshold of them all, into [a.aa] *)
let rec least_threshold (a : at) = function
  | [] -> ()
  | (i : Interior.t) :: r ->
      least_in a i.media;
      least_threshold a r

and least_in a = function
  | [] -> ()
  | (m : Media.t) :: ms ->
      if m.aa_threshold < a.aa then a.aa <- m.aa_threshold;
      least_in a ms

(* a stretch's light, dimmed by the depth before it *)
let gather st =
  let x = st.sumx and c = st.sum and od = st.od and g = st.got in
  Color.acc_set g
    (g.ar +. (c.ar *. Float.exp (-.od.ar)))
    (g.ag +. (c.ag *. Float.exp (-.od.ag)))
    (g.ab +. (c.ab *. Float.exp (-.od.ab)));
  Color.acc_set od (od.ar +. x.ar) (od.ag +. x.ag) (od.ab +. x.ab)

(* one of POV-Ray's sampling intervals, [st.at.lo, st.at.hi] along the
   ray, sampled by [m0]'s method into [st.od] and [st.got] *)
let interval s st inside (m0 : Media.t) =
  let a = st.at.lo in
  let ds = st.at.hi -. a in
  if m0.meth = 2 then begin
    (* [samples] midpoints, each dimmed by its own extinction over its
       distance into the interval, the interval by the depth before it
       (POV-Ray 3.7's rule: exact for constant media) *)
    let n = max 1 m0.samples in
    let k = 1. /. float_of_int n in
    Color.acc_set st.sumx 0. 0. 0.;
    Color.acc_set st.sum 0. 0. 0.;
    for i = 0 to n - 1 do
      let d0 = ds *. (float_of_int i +. 0.5) *. k in
      st.at.x <- a +. d0;
      sample s st inside 0;
      let b = st.buf and kd = k *. ds and sx = st.sumx and sm = st.sum in
      Color.acc_set sx
        (sx.ar +. (kd *. Float.Array.get b 0))
        (sx.ag +. (kd *. Float.Array.get b 1))
        (sx.ab +. (kd *. Float.Array.get b 2));
      Color.acc_set sm
        (sm.ar +. (kd *. Float.Array.get b 3 *. Float.exp (-.(Float.Array.get b 0 *. d0))))
        (sm.ag +. (kd *. Float.Array.get b 4 *. Float.exp (-.(Float.Array.get b 1 *. d0))))
        (sm.ab +. (kd *. Float.Array.get b 5 *. Float.exp (-.(Float.Array.get b 2 *. d0))))
    done;
    gather st
  end
  else begin
    let n = Media.pieces m0 in
    let w = ds /. float_of_int n in
    let step = ds /. float_of_int (n + 1) in
    st.at.x <- a;
    sample s st inside 0;
    st.at.thr <- st.at.aa /. ds;
    for i = 0 to n - 1 do
      let x = a +. (step *. float_of_int i) in
      (* ends alternate between slots 0 and 1 *)
      let ka = i land 1 and kb = 1 - (i land 1) in
      st.at.x <- x +. step;
      sample s st inside kb;
      Color.acc_set st.sumx 0. 0. 0.;
      Color.acc_set st.sum 0. 0. 0.;
      push st 0 x (x +. step) w;
      (* POV-Ray's aa_level counts the stretch itself *)
      stretch s st inside ka kb 0 (m0.aa_level - 1);
      gather st
    done
  end

let weight lt (m0 : Media.t) i = if Lit.is_lit lt i then m0.ratio else 1. -. m0.ratio

(* POV-Ray's sampling intervals: at least [intervals] of them, at least one
   per lit or unlit stretch, shared among the stretches by [ratio] (the lit
   ones take [ratio] of them) when there are several; a single stretch is
   cut into [intervals] even parts, or left whole when it is unlit and the
   medium constant *)
let intervals s st inside (m0 : Media.t) =
  let lt = st.lit_spans in
  let nlit = Lit.count lt in
  let total = max m0.intervals nlit in
  if nlit = 1 then begin
    let a = Lit.lo lt 0 and b = Lit.hi lt 0 in
    st.lit_now <- Lit.is_lit lt 0;
    if (not (Lit.is_lit lt 0)) && Media.constant m0 then begin
      st.at.lo <- a;
      st.at.hi <- b;
      interval s st inside m0
    end
    else
      let d = (b -. a) /. float_of_int total in
      for j = 0 to total - 1 do
        st.at.lo <- a +. (d *. float_of_int j);
        st.at.hi <- a +. (d *. float_of_int (j + 1));
        interval s st inside m0
      done
  end
  else begin
    let sum = ref 0. in
    for i = 0 to nlit - 1 do
      sum := !sum +. weight lt m0 i
    done;
    let remaining = ref total in
    for i = 0 to nlit - 1 do
      let n = int_of_float (weight lt m0 i /. !sum *. float_of_int total) + 1 in
      let n = min n (!remaining - nlit + i + 1) in
      let a = Lit.lo lt i in
      let d = (Lit.hi lt i -. a) /. float_of_int n in
      st.lit_now <- Lit.is_lit lt i;
      for j = 0 to n - 1 do
        st.at.lo <- a +. (d *. float_of_int j);
        st.at.hi <- a +. (d *. float_of_int (j + 1));
        interval s st inside m0
      done;
      remaining := !remaining - n
    done
  end

let[@inline] apply (s : Scene.t) (o : Vec3.m) (d : Vec3.m) t ~starts inside (out : Color.acc) =
  match first_media inside with
  | [] -> ()
  | _ :: _ when Float.is_finite t ->
      let m0 = most_intervals inside in
      let st = Scratch.get key in
      st.at.aa <- infinity;
      least_threshold st.at inside;
      st.count <- count inside;
      st.starts <- starts;
      let dl = Float.sqrt ((d.mx *. d.mx) +. (d.my *. d.my) +. (d.mz *. d.mz)) in
      let r = st.r in
      r.ox <- o.mx; r.oy <- o.my; r.oz <- o.mz;
      r.dx <- d.mx /. dl; r.dy <- d.my /. dl; r.dz <- d.mz /. dl;
      let len = t *. dl in
      Lit.cut st.lit_spans s.lights r len;
      Color.acc_set st.od 0. 0. 0.;
      Color.acc_set st.got 0. 0. 0.;
      intervals s st inside m0;
      let od = st.od and g = st.got in
      Color.acc_set out
        ((out.ar *. Float.exp (-.od.ar)) +. g.ar)
        ((out.ag *. Float.exp (-.od.ag)) +. g.ag)
        ((out.ab *. Float.exp (-.od.ab)) +. g.ab)
  | _ :: _ -> ()

(* POV-Ray 3.7's participating media (see media.mli). *)

type scattering = { kind : int; color : Color.t; eccentricity : float; extinction : float }

type t = {
  emission : Color.t;
  absorption : Color.t;
  scattering : scattering option;
  density : Pigment.t list;
  meth : int;
  intervals : int;
  samples : int;
  samples_max : int;
  aa_threshold : float;
  aa_level : int;
  jitter : float;
  confidence : float;
  variance : float;
  ratio : float;
  collect : bool;
  mutable bound : float;
}

let default =
  { emission = Color.black; absorption = Color.black; scattering = None; density = []; meth = 3;
    intervals = 1; samples = 10; samples_max = 10; aa_threshold = 0.1; aa_level = 3; jitter = 0.;
    confidence = 0.9; variance = 1. /. 128.; ratio = 0.9; collect = true; bound = -1. }

let scattering kind color = { kind; color; eccentricity = 0.; extinction = 1. }
let transform t m = if m.density = [] then m else { m with density = List.map (Pigment.transform t) m.density }
let constant m = m.density = []

(* POV-Ray's constants, read from its pictures: each phase function
   averages 1 over the sphere *)
let phase sc c =
  match sc.kind with
  | 2 ->
      let x = 0.5 *. (1. +. c) in
      let x2 = x *. x in
      let x4 = x2 *. x2 in
      0.57666 *. (1. +. (9. *. x4 *. x4))
  | 3 -> 0.4957 *. (1. +. (50. *. Float.pow (0.5 *. (1. +. c)) 32.))
  | 4 -> 0.79937 *. (1. +. (c *. c))
  | 5 ->
      let g = sc.eccentricity in
      let k = 1. +. (g *. g) -. (2. *. g *. c) in
      (1. -. (g *. g)) /. (k *. Float.sqrt k)
  | _ -> 1.

(* The product of the densities at [p] (POV-Ray's product, in the order
   written), up to the first that leaves it zero: further factors
   (finite colours) leave it zero, but for the sign of a zero, and the
   rest of the list is not evaluated (advanced/benchmark's clouds: a
   7-octave turbulence skipped wherever the wrinkles before it are 0) *)
let rec densities l p (pig : Pigment.out) (out : Color.acc) =
  match l with
  | [] -> ()
  | d :: r ->
      Pigment.into d p pig;
      Color.acc_set out (out.ar *. pig.r) (out.ag *. pig.g) (out.ab *. pig.b);
      if out.ar <> 0. || out.ag <> 0. || out.ab <> 0. then densities r p pig out

let density_into m p pig (out : Color.acc) =
  Color.acc_set out 1. 1. 1.;
  densities m.density p pig out

(* the extinction of [m] at [p] added into [out] ([dens]: scratch) *)
let add_extinction m p pig (dens : Color.acc) (out : Color.acc) =
  let er, eg, eb =
    match m.scattering with
    | None -> (m.absorption.r, m.absorption.g, m.absorption.b)
    | Some s ->
        ( m.absorption.r +. (s.extinction *. s.color.r),
          m.absorption.g +. (s.extinction *. s.color.g),
          m.absorption.b +. (s.extinction *. s.color.b) )
  in
  if m.density = [] then Color.acc_set out (out.ar +. er) (out.ag +. eg) (out.ab +. eb)
  else begin
    density_into m p pig dens;
    Color.acc_set out (out.ar +. (er *. dens.ar)) (out.ag +. (eg *. dens.ag)) (out.ab +. (eb *. dens.ab))
  end

(* POV-Ray 3.7's method 3 splits an interval into [pieces] stretches of
   1/(pieces + 1) of it, each sampled at its ends and middle, each
   standing for 1/pieces of the interval (measured on its pictures) *)
let pieces m = if m.meth = 2 then m.samples * m.intervals else max 2 ((m.samples / 2) + 1)

(* [od]: the optical depth summed along a stretch (kept here: refs
   captured by a closure would box every float added) *)
type depth_scratch = { q : Vec3.m; pig : Pigment.out; dens : Color.acc; ext : Color.acc; od : Color.acc }

let depth_key =
  Scratch.key (fun () -> { q = Vec3.m (); pig = Pigment.out (); dens = Color.acc 0.; ext = Color.acc 0.; od = Color.acc 0. })

let rec add_all ms p pig dens out =
  match ms with
  | [] -> ()
  | m :: r ->
      add_extinction m p pig dens out;
      add_all r p pig dens out

let all_constant ms = List.for_all constant ms

(* the extinction of all of [ms] at [x] along the ray, into [st.ext] *)
let ext_at ms (r : Ray.scratch) x st =
  Vec3.set st.q (r.ox +. (x *. r.dx)) (r.oy +. (x *. r.dy)) (r.oz +. (x *. r.dz));
  Color.acc_set st.ext 0. 0. 0.;
  add_all ms st.q st.pig st.dens st.ext

(* [k] times the extinction at [x] along [r], added to [st.od] *)
let[@inline] add_depth ms r st k x =
  ext_at ms r x st;
  let od = st.od and e = st.ext in
  Color.acc_set od (od.ar +. (k *. e.ar)) (od.ag +. (k *. e.ag)) (od.ab +. (k *. e.ab))

type span = { mutable lo : float; mutable hi : float }

let span () = { lo = 0.; hi = 0. }

let transmittance_into ms (r : Ray.scratch) (sp : span) (out : Color.acc) =
  match ms with
  | [] -> ()
  | m0 :: _ ->
      let st = Scratch.get depth_key in
      let lo = sp.lo in
      let len = sp.hi -. lo in
      let od = st.od in
      if all_constant ms then begin
        ext_at ms r lo st;
        Color.acc_set od (st.ext.ar *. len) (st.ext.ag *. len) (st.ext.ab *. len)
      end
      else begin
        Color.acc_set od 0. 0. 0.;
        let n = pieces m0 in
        if m0.meth = 2 then
          for i = 0 to n - 1 do
            add_depth ms r st (len /. float_of_int n) (lo +. (len *. (float_of_int i +. 0.5) /. float_of_int n))
          done
        else
          let step = len /. float_of_int (n + 1) and k = len /. float_of_int n /. 3. in
          for i = 0 to n - 1 do
            let a = lo +. (step *. float_of_int i) in
            add_depth ms r st k a;
            add_depth ms r st k (a +. (0.5 *. step));
            add_depth ms r st k (a +. step)
          done
      end;
      Color.acc_set out (out.ar *. Float.exp (-.od.ar)) (out.ag *. Float.exp (-.od.ag)) (out.ab *. Float.exp (-.od.ab))

(* the majorant, worked out once: the extinction's largest channel (by
   [add_extinction]'s formula) times the densities' bounds *)
let[@inline never] fill_bound m =
  let e = Color.acc 0. in
  add_extinction { m with density = [] } (Vec3.m ()) (Pigment.out ()) (Color.acc 0.) e;
  let top = Float.max (Float.abs e.ar) (Float.max (Float.abs e.ag) (Float.abs e.ab)) in
  m.bound <- List.fold_left (fun a d -> a *. Pigment.bound d) top m.density

let[@inline] majorant m =
  if m.bound < 0. then fill_bound m;
  m.bound

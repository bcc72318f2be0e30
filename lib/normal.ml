type t = {
  pattern : Pattern.t;
  amount : float;
  xform : Transform.t;
  slope : Float.Array.t;
  accuracy : float;
  map : map;
}

and map =
  | Leaf
  | Blend of (float * t) array
  | Average of (float * t) array
  | Cells of t array
  | Image of Bump_map.t
  | Facets of Facets.t
  | Uv of { entry : t; turns : bool }

(* the pattern value of a slope map's [i]th entry *)
let[@inline] entry_value m i = Float.Array.unsafe_get m (3 * i)

(* inlined: its float argument and result stay unboxed *)
let[@inline] slope_height m v =
  let n = Float.Array.length m / 3 in
  if v <= entry_value m 0 then Float.Array.unsafe_get m 1
  else if v >= entry_value m (n - 1) then Float.Array.unsafe_get m ((3 * (n - 1)) + 1)
  else begin
    let i = ref 1 in
    while v > entry_value m !i do incr i done;
    let a = 3 * (!i - 1) and b = 3 * !i in
    let v0 = Float.Array.unsafe_get m a and h0 = Float.Array.unsafe_get m (a + 1)
    and s0 = Float.Array.unsafe_get m (a + 2) in
    let v1 = Float.Array.unsafe_get m b and h1 = Float.Array.unsafe_get m (b + 1)
    and s1 = Float.Array.unsafe_get m (b + 2) in
    if v1 = v0 then h1
    else
      (* Hermite: heights h0, h1 and slopes s0, s1 at t = 0, 1 *)
      let t = (v -. v0) /. (v1 -. v0) in
      let t2 = t *. t in
      let t3 = t2 *. t in
      (t3 *. (s0 +. s1 +. (2. *. (h0 -. h1)))) -. (t2 *. ((2. *. s0) +. s1 +. (3. *. (h0 -. h1)))) +. (t *. s0) +. h0
  end

(* POV-Ray's default accuracy: the samples' distance (see [perturb_m]) *)
let default_accuracy = 0.02

let make kind amount =
  { pattern = Pattern.make kind; amount; xform = Transform.identity; slope = Float.Array.create 0;
    accuracy = default_accuracy; map = Leaf }
(* a uv-mapped normal written as such ignores the transformations after
   it; one made by a uv-mapped texture keeps them as its frame *)
let transform t nm =
  match nm.map with Uv { turns = false; _ } -> nm | _ -> { nm with xform = Transform.then_ nm.xform t }

let uv ~turns nm =
  match nm.map with
  | Uv u -> { nm with map = Uv { u with turns = u.turns || turns } }
  | _ ->
      { pattern = Pattern.make Pattern.Bozo; amount = 0.; xform = Transform.identity; slope = Float.Array.create 0;
        accuracy = default_accuracy; map = Uv { entry = nm; turns } }

let rec uses_uv nm =
  match nm.map with
  | Uv _ -> true
  | Leaf | Image _ | Facets _ -> false
  | Blend es | Average es -> Array.exists (fun (_, e) -> uses_uv e) es
  | Cells cs -> Array.exists uses_uv cs

(* Bump strength per unit of amount and of pattern-space slope, calibrated
   on POV-Ray renders of smooth exact patterns (leopard). *)
let strength = 2. /. 15.

(* The slope of the pattern is estimated as POV-Ray does (measured with
   povray 3.7 on normal { gradient x }: the dark bands at each jump of the
   pattern are 0.02 wide ahead and 0.01 behind, and their shading matches
   to 5 digits): the pattern sampled at the four corners of a regular
   tetrahedron of radius [delta] around the point, one corner on +y;
   g = 3/(4 delta) sum v_i f(q + delta v_i), exact for a linear pattern;
   delta is the normal's accuracy, 0.02 by default. The corners are
   POV-Ray's (normal.cpp's Pyramid_Vect, written to 9 digits) and the
   accuracy is taken in single precision (POV-Ray keeps it in a float:
   0.02 is 0.0199999995529...): a sample that falls on a pixel's edge of
   an image pattern then reads the pixel POV-Ray reads (measured: a
   plane y = 0.37 under normal { image_pattern { png "W x 200" } },
   whose top corner lands on the row edge at 0.39, went from 20.2 dB of
   POV-Ray's picture to identical). *)
let tetra =
  [| Vec3.make 0.942809041 (-0.333333333) 0.; Vec3.make (-0.471404521) (-0.333333333) 0.816496581;
     Vec3.make (-0.471404521) (-0.333333333) (-0.816496581); Vec3.make 0. 1. 0. |]

let single x = Int32.float_of_bits (Int32.bits_of_float x)

(* Per domain: the point in pattern space, a sample around it, the
   pattern's work. *)
type level = { lq : Vec3.m; ln : Vec3.m; t0 : Vec3.m; t1 : Vec3.m }

type work = { q : Vec3.m; s : Vec3.m; pw : Pattern.work; lv : level Scratch.levels; mutable used : int }

let work_key =
  Scratch.key (fun () ->
      { q = Vec3.m (); s = Vec3.m (); pw = Pattern.work ();
        lv = Scratch.levels (fun () -> { lq = Vec3.m (); ln = Vec3.m (); t0 = Vec3.m (); t1 = Vec3.m () });
        used = 0 })

(* POV-Ray's quilted normal: in pattern space, the offset from the
   cell's centre scaled by quilted's cubic of its length, times the
   amount, added to the unit normal *)
let quilted_m nm c0 c1 (q : Vec3.m) (n : Vec3.m) (out : Vec3.m) =
  let vx = q.mx -. Float.floor q.mx -. 0.5 and vy = q.my -. Float.floor q.my -. 0.5
  and vz = q.mz -. Float.floor q.mz -. 0.5 in
  let k = nm.amount *. Pattern.quilt_cubic (Float.sqrt ((vx *. vx) +. (vy *. vy) +. (vz *. vz))) c0 c1 in
  Vec3.set out n.mx n.my n.mz;
  Transform.normal_inverse_m nm.xform out;
  Vec3.normalize_m out;
  Vec3.set out (out.mx +. (k *. vx)) (out.my +. (k *. vy)) (out.mz +. (k *. vz));
  Transform.normal_m nm.xform out;
  if (out.mx *. out.mx) +. (out.my *. out.my) +. (out.mz *. out.mz) = 0. then Vec3.set out n.mx n.my n.mz
  else Vec3.normalize_m out

(* POV-Ray's ripples and waves normals: in pattern space (warped), the
   unit normal plus amount / (number of sources) times, for each source
   c, the unit vector from c times the wave at the distance d from it,
   sin (2 pi (d frequency + phase)). waves takes the cosine: camlray's
   waves pattern is the quarter-wave shift of ripples (POV-Ray's gives
   each source a frequency of its own, from its noise). *)
let waves_m w nm ripples (q : Vec3.m) (n : Vec3.m) (out : Vec3.m) =
  let t = nm.pattern in
  Pattern.warped_m t q w.pw;
  let p = w.pw.p in
  let sources = Pattern.sources in
  let k = nm.amount /. float_of_int (Array.length sources) in
  let two_pi = 2. *. Float.pi in
  Vec3.set out n.mx n.my n.mz;
  Transform.normal_inverse_m nm.xform out;
  Vec3.normalize_m out;
  for i = 0 to Array.length sources - 1 do
    let (c : Vec3.t) = Array.unsafe_get sources i in
    let vx = p.mx -. c.x and vy = p.my -. c.y and vz = p.mz -. c.z in
    let d = Float.sqrt ((vx *. vx) +. (vy *. vy) +. (vz *. vz)) in
    let d = if d = 0. then 1. else d in
    let a = two_pi *. ((d *. t.frequency) +. t.phase) in
    let s = k *. (if ripples then Float.sin a else Float.cos a) /. d in
    Vec3.set out (out.mx +. (s *. vx)) (out.my +. (s *. vy)) (out.mz +. (s *. vz))
  done;
  Transform.normal_m nm.xform out;
  if (out.mx *. out.mx) +. (out.my *. out.my) +. (out.mz *. out.mz) = 0. then Vec3.set out n.mx n.my n.mz
  else Vec3.normalize_m out

let leaf_m w nm (point : Vec3.m) (n : Vec3.m) (out : Vec3.m) =
  let q = w.q in
  Transform.inv_point_m nm.xform point q;
  match nm.pattern.kind with
  | Pattern.Quilted { c0; c1 } -> quilted_m nm c0 c1 q n out
  | (Pattern.Ripples | Pattern.Waves) as kind when Float.Array.length nm.slope = 0 ->
      waves_m w nm (kind = Pattern.Ripples) q n out
  | _ ->
  (* g = 3/(4 delta) sum v_i f(q + delta v_i), summed in order; delta the
     normal's accuracy *)
  let delta = single nm.accuracy in
  let gx = ref 0. and gy = ref 0. and gz = ref 0. in
  for i = 0 to Array.length tetra - 1 do
    let (v : Vec3.t) = Array.unsafe_get tetra i in
    Vec3.set w.s (q.mx +. (delta *. v.x)) (q.my +. (delta *. v.y)) (q.mz +. (delta *. v.z));
    Pattern.eval_m nm.pattern w.s w.pw;
    let f = if Float.Array.length nm.slope = 0 then w.pw.r.v else slope_height nm.slope w.pw.r.v in
    gx := !gx +. (f *. v.x);
    gy := !gy +. (f *. v.y);
    gz := !gz +. (f *. v.z)
  done;
  let c = 3. /. (4. *. delta) in
  let gx = c *. !gx and gy = c *. !gy and gz = c *. !gz in
  (* as POV-Ray: tilt a unit normal in pattern space, then bring it back *)
  Vec3.set out n.mx n.my n.mz;
  Transform.normal_inverse_m nm.xform out;
  Vec3.normalize_m out;
  (* POV-Ray computes bumps, dents, ripples, waves and wrinkles with
     formulas of their own, much stronger than the generic slope; these
     gains make camlray's look alike (set by eye: the noise differs) *)
  let gain =
    match nm.pattern.kind with
    | Pattern.Bozo | Pattern.Bumps | Pattern.Spotted | Pattern.Ripples | Pattern.Waves -> 12.
    | Pattern.Dents -> 1.5
    | Pattern.Wrinkles | Pattern.Granite -> 0.6
    | _ -> 1.
  in
  (* the full slope, normal component included *)
  let k = -.nm.amount *. strength *. gain in
  Vec3.set out (out.mx +. (k *. gx)) (out.my +. (k *. gy)) (out.mz +. (k *. gz));
  Transform.normal_m nm.xform out;
  if (out.mx *. out.mx) +. (out.my *. out.my) +. (out.mz *. out.mz) = 0. then Vec3.set out n.mx n.my n.mz
  else Vec3.normalize_m out

(* POV-Ray's normal_map, average and block lists (measured with povray
   3.7, see docs/language.md): the point and the unit normal are taken to
   the map's own pattern space; there the entries perturb the normal (their
   transforms relative to that space), their unit results are summed with
   the weights (the two entries around the pattern's value: 1 - k and k;
   average: the weights over their sum), and the sum is brought back to
   world space and normalised. Depth [d] keeps a level's work apart from
   the nested maps' below it. *)
let rec perturb_d w nm (point : Vec3.m) (n : Vec3.m) (out : Vec3.m) d =
  match nm.map with
  | Leaf -> leaf_m w nm point n out
  | map ->
      let l = Scratch.level w.lv d in
      if w.used <= d then w.used <- d + 1;
      (match map with
      | Blend entries ->
          let v = Pattern.eval_at nm.pattern nm.xform point w.pw in
          into_warped w nm n l;
          let k = Array.length entries in
          let i = Pattern.around entries v in
          if i = 0 then perturb_d w (snd entries.(0)) l.lq l.ln out (d + 1)
          else if i >= k then perturb_d w (snd entries.(k - 1)) l.lq l.ln out (d + 1)
          else begin
            let vi, ei = entries.(i) and vp, ep = entries.(i - 1) in
            if vi -. vp <= 0. then perturb_d w ei l.lq l.ln out (d + 1)
            else begin
              let k = (v -. vp) /. (vi -. vp) in
              perturb_d w ep l.lq l.ln l.t0 (d + 1);
              perturb_d w ei l.lq l.ln l.t1 (d + 1);
              let a = 1. -. k in
              Vec3.set out ((a *. l.t0.mx) +. (k *. l.t1.mx)) ((a *. l.t0.my) +. (k *. l.t1.my))
                ((a *. l.t0.mz) +. (k *. l.t1.mz))
            end
          end
      | Cells cells ->
          let v = Pattern.eval_at nm.pattern nm.xform point w.pw in
          into_warped w nm n l;
          let k = Array.length cells in
          perturb_d w cells.(Int.min (k - 1) (Int.max 0 (int_of_float v))) l.lq l.ln out (d + 1)
      | Average entries ->
          into_space nm point n l;
          warp_point w nm l;
          Vec3.set l.t1 0. 0. 0.;
          for i = 0 to Array.length entries - 1 do
            let wt, e = Array.unsafe_get entries i in
            perturb_d w e l.lq l.ln l.t0 (d + 1);
            Vec3.set l.t1 (l.t1.mx +. (wt *. l.t0.mx)) (l.t1.my +. (wt *. l.t0.my)) (l.t1.mz +. (wt *. l.t0.mz))
          done;
          Vec3.set out l.t1.mx l.t1.my l.t1.mz
      | Image b ->
          into_space nm point n l;
          warp_point w nm l;
          Bump_map.tilt b nm.amount l.lq l.ln out
      | Facets f ->
          (* POV-Ray's facets: the point warped, the amount unused *)
          into_space nm point n l;
          Pattern.warped_m nm.pattern l.lq w.pw;
          Facets.tilt_m f w.pw.p l.ln out
      | Uv { entry; _ } ->
          (* POV-Ray's uv_mapping (measured): the entry's pattern taken at
             the surface's <u, v, 0>, the normal as it is in this space
             (world space, or the frame of the transformations written
             after a uv-mapped texture) *)
          into_space nm point n l;
          perturb_d w entry (Pattern.uv_point ()) l.ln out (d + 1)
      | Leaf -> ());
      Transform.normal_m nm.xform out;
      if (out.mx *. out.mx) +. (out.my *. out.my) +. (out.mz *. out.mz) = 0. then Vec3.set out n.mx n.my n.mz
      else Vec3.normalize_m out

and into_space nm point n l =
  Transform.inv_point_m nm.xform point l.lq;
  into_frame nm n l

(* POV-Ray 3.7 warps the point of a bump map and of an average: the
   warps and turbulence [nm.pattern] carries (its kind unused), the
   normal as it is in this space *)
and warp_point w nm l = Pattern.warp_in_place nm.pattern l.lq w.pw

and into_frame nm n l =
  Vec3.set l.ln n.mx n.my n.mz;
  Transform.normal_inverse_m nm.xform l.ln;
  Vec3.normalize_m l.ln

(* POV-Ray 3.7 (normal.cpp's Perturb_Normal): a normal_map's entries are
   taken at the point its pattern was just evaluated at (its warps and
   turbulence applied), the normal turned by its transformations only *)
and into_warped w nm n l =
  let p = Pattern.entries_point nm.pattern w.pw in
  Vec3.set l.lq p.mx p.my p.mz;
  into_frame nm n l

let perturb_m nm point n out =
  let w = Scratch.get work_key in
  match nm.map with
  | Leaf -> leaf_m w nm point n out
  | _ ->
      (* a normal in a pattern function may start inside another's work *)
      let base = w.used in
      perturb_d w nm point n out base;
      w.used <- base

let perturb_through nm point (n : Vec3.m) (chain : Transform.t array) nchain (tn : Vec3.m) (out : Vec3.m) =
  if nchain = 0 then perturb_m nm point n out
  else begin
    Vec3.set tn n.mx n.my n.mz;
    for i = 0 to nchain - 1 do
      Transform.normal_inverse_m (Array.unsafe_get chain i) tn;
      Vec3.normalize_m tn
    done;
    perturb_m nm point tn out;
    for i = nchain - 1 downto 0 do
      Transform.normal_m (Array.unsafe_get chain i) out;
      Vec3.normalize_m out
    done
  end

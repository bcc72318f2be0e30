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

(* The slope of the pattern is estimated as POV-Ray does (normal.cpp's
   Perturb_Normal for the patterns without a formula of their own;
   measured with povray 3.7 on normal { gradient x }: the dark bands at
   each jump of the pattern are 0.02 wide ahead and 0.01 behind, and
   their shading matches to 5 digits): the pattern sampled at the four
   corners v_i of a regular tetrahedron of radius [delta] around the
   point, one corner on +y, and the unit normal moved by -5 amount (0.02
   / delta) f(q + delta v_i) v_i, corner by corner (exact for a linear
   pattern: a tilt of amount/10 per unit of slope, whatever delta);
   delta is the normal's accuracy, 0.02 by default. The corners are
   POV-Ray's (normal.cpp's Pyramid_Vect, written to 9 digits), and the
   accuracy and the amount are taken in single precision (POV-Ray keeps
   them in floats: 0.02 is 0.0199999995529...): a sample that falls on a
   pixel's edge of an image pattern then reads the pixel POV-Ray reads
   (measured: a plane y = 0.37 under normal { image_pattern { png "W x
   200" } }, whose top corner lands on the row edge at 0.39, went from
   20.2 dB of POV-Ray's picture to identical). The point is warped once,
   at the centre, and the pattern taken unwarped at the corners around
   it, as POV-Ray does (Warp_EPoint, then Evaluate_TPat at each corner):
   the slope is the pattern's own, not the warped pattern's. *)
let tetra =
  [| Vec3.make 0.942809041 (-0.333333333) 0.; Vec3.make (-0.471404521) (-0.333333333) 0.816496581;
     Vec3.make (-0.471404521) (-0.333333333) (-0.816496581); Vec3.make 0. 1. 0. |]

let single = Floats.single

(* Per domain: the point in pattern space, a sample around it, the
   pattern's work. *)
type level = { lq : Vec3.m; ln : Vec3.m; t0 : Vec3.m; t1 : Vec3.m }

type work = { q : Vec3.m; s : Vec3.m; c : Vec3.m; pw : Pattern.work; lv : level Scratch.levels; mutable used : int }

let work_key =
  Scratch.key (fun () ->
      { q = Vec3.m (); s = Vec3.m (); c = Vec3.m (); pw = Pattern.work ();
        lv = Scratch.levels (fun () -> { lq = Vec3.m (); ln = Vec3.m (); t0 = Vec3.m (); t1 = Vec3.m () });
        used = 0 })

(* POV-Ray's FLOOR (texture.h): floor, but a negative whole number
   goes one lower *)
let[@inline] pov_floor x = if x >= 0. then Float.floor x else 0. -. Float.floor (0. -. x) -. 1.

(* The unit normal [n] taken to the normal's pattern space (turned by
   its transformations, made unit), into [out] *)
let[@inline] into_pattern nm (n : Vec3.m) (out : Vec3.m) =
  Vec3.set out n.mx n.my n.mz;
  Transform.normal_inverse_m nm.xform out;
  Vec3.normalize_m out

(* and back: turned to world space and made unit ([n] itself if nothing
   is left) *)
let[@inline] back_from_pattern nm (n : Vec3.m) (out : Vec3.m) =
  Transform.normal_m nm.xform out;
  if (out.mx *. out.mx) +. (out.my *. out.my) +. (out.mz *. out.mz) = 0. then Vec3.set out n.mx n.my n.mz
  else Vec3.normalize_m out

(* POV-Ray 3.7's normals with formulas of their own (normal.cpp: bumps,
   dents, wrinkles, ripples, waves), at the point [q] of pattern space
   (warped there): the unit normal in pattern space moved by
   - bumps: amount DNoise(p);
   - dents: amount Noise(p)^3 DNoise(p) (the pattern's noise generator);
   - wrinkles: amount sum_{i < 10} |DNoise(2^i p)| / 2^i (componentwise);
   - ripples: for each wave source c (see {!Pattern.waves}), at the
     distance d = |p - c| (1 at c), amount sin(d frequency + phase) / (n
     d) (p - c), the sine POV-Ray's cycloidal (in turns), n sources;
   - waves: the same with d frequency f_c + phase and the sine divided by
     the source's own frequency f_c;
   - quilted: amount v c(|v|), v the offset from the cell's centre (cells
     by POV-Ray's FLOOR), c quilted's cubic;
   then brought back. The amount, frequency and phase in single
   precision, as POV-Ray keeps them. A slope_map is unused, as in
   POV-Ray. *)
let own_m w nm (q : Vec3.m) (n : Vec3.m) (out : Vec3.m) =
  let t = nm.pattern in
  Pattern.warped_m t q w.pw;
  let p = w.pw.p and d = w.s in
  let a = single nm.amount in
  into_pattern nm n out;
  (match t.kind with
  | Pattern.Bumps ->
      Noise.dnoise p.mx p.my p.mz d;
      Vec3.set out (out.mx +. (a *. d.mx)) (out.my +. (a *. d.my)) (out.mz +. (a *. d.mz))
  | Pattern.Dents ->
      let v = Noise.noise (Pattern.generator t) p.mx p.my p.mz in
      let k = v *. v *. v *. a in
      Noise.dnoise p.mx p.my p.mz d;
      Vec3.set out (out.mx +. (k *. d.mx)) (out.my +. (k *. d.my)) (out.mz +. (k *. d.mz))
  | Pattern.Wrinkles ->
      let rx = ref 0. and ry = ref 0. and rz = ref 0. and sc = ref 1. in
      for _ = 0 to 9 do
        let s = !sc in
        Noise.dnoise (p.mx *. s) (p.my *. s) (p.mz *. s) d;
        rx := !rx +. Float.abs (d.mx /. s);
        ry := !ry +. Float.abs (d.my /. s);
        rz := !rz +. Float.abs (d.mz /. s);
        sc := s *. 2.
      done;
      Vec3.set out (out.mx +. (a *. !rx)) (out.my +. (a *. !ry)) (out.mz +. (a *. !rz))
  | Pattern.Quilted { c0; c1 } ->
      let vx = p.mx -. pov_floor p.mx -. 0.5 and vy = p.my -. pov_floor p.my -. 0.5
      and vz = p.mz -. pov_floor p.mz -. 0.5 in
      let c = Pattern.quilt_cubic (Float.sqrt ((vx *. vx) +. (vy *. vy) +. (vz *. vz))) c0 c1 in
      Vec3.set out (out.mx +. (a *. (vx *. c))) (out.my +. (a *. (vy *. c))) (out.mz +. (a *. (vz *. c)))
  | _ ->
      (* ripples, waves *)
      let wv = Pattern.waves () in
      let ripples = match t.kind with Pattern.Ripples -> true | _ -> false in
      (* frequency and phase already single, as the parser stores them *)
      let freq = t.frequency and phase = t.phase in
      let nf = float_of_int wv.count in
      for i = 0 to wv.count - 1 do
        let vx = p.mx -. Float.Array.unsafe_get wv.src (3 * i)
        and vy = p.my -. Float.Array.unsafe_get wv.src ((3 * i) + 1)
        and vz = p.mz -. Float.Array.unsafe_get wv.src ((3 * i) + 2) in
        let l = Float.sqrt ((vx *. vx) +. (vy *. vy) +. (vz *. vz)) in
        let l = if l = 0. then 1. else l in
        let scalar =
          if ripples then Pattern.cycloidal ((l *. freq) +. phase) *. a
          else begin
            let f = Float.Array.unsafe_get wv.freq i in
            Pattern.cycloidal ((l *. freq *. f) +. phase) *. a /. f
          end
        in
        let k = scalar /. (l *. nf) in
        Vec3.set out (out.mx +. (k *. vx)) (out.my +. (k *. vy)) (out.mz +. (k *. vz))
      done);
  back_from_pattern nm n out

(* marble and wood take their turbulence themselves in POV-Ray (at each
   corner of the slope's tetrahedron, not at its centre) *)
let[@inline] own_turbulence (t : Pattern.t) =
  match (t.kind, t.turbulence) with (Pattern.Marble | Pattern.Wood), Some _ -> true | _ -> false

let leaf_m w nm (point : Vec3.m) (n : Vec3.m) (out : Vec3.m) =
  let q = w.q in
  Transform.inv_point_m nm.xform point q;
  let t = nm.pattern in
  match t.kind with
  | Pattern.Bumps | Pattern.Dents | Pattern.Wrinkles | Pattern.Ripples | Pattern.Waves | Pattern.Quilted _ ->
      own_m w nm q n out
  | _ ->
      let delta = single nm.accuracy in
      let k = single nm.amount *. -5. *. (0.02 /. delta) in
      let per_corner = own_turbulence t in
      (* the centre, warped *)
      let c = w.c in
      if per_corner then Vec3.set c q.mx q.my q.mz
      else begin
        Pattern.warped_m t q w.pw;
        Vec3.set c w.pw.p.mx w.pw.p.my w.pw.p.mz
      end;
      into_pattern nm n out;
      for i = 0 to Array.length tetra - 1 do
        let (v : Vec3.t) = Array.unsafe_get tetra i in
        Vec3.set w.s (c.mx +. (delta *. v.x)) (c.my +. (delta *. v.y)) (c.mz +. (delta *. v.z));
        if per_corner then Pattern.eval_m t w.s w.pw
        else begin
          Vec3.set w.pw.p w.s.mx w.s.my w.s.mz;
          Pattern.eval_warped t w.pw
        end;
        let f = if Float.Array.length nm.slope = 0 then w.pw.r.v else slope_height nm.slope w.pw.r.v in
        let fk = f *. k in
        Vec3.set out (out.mx +. (fk *. v.x)) (out.my +. (fk *. v.y)) (out.mz +. (fk *. v.z))
      done;
      back_from_pattern nm n out

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
      back_from_pattern nm n out

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

(* Where rays cross spotlights' cones (POV-Ray's light-source intervals
   for media): the stretch found against points tested one by one, and
   how the lit parts of several lights are merged. *)
open Camlray

let spot ?(interaction = true) pos at falloff =
  {
    (Light.point pos Color.white) with
    kind = Light.spot ~point_at:at ~radius:falloff ~falloff ~tightness:0.;
    media_interaction = interaction;
  }

let ray (o : Vec3.t) (d : Vec3.t) =
  let r = Ray.scratch () in
  let d = Vec3.normalize d in
  r.ox <- o.x; r.oy <- o.y; r.oz <- o.z;
  r.dx <- d.x; r.dy <- d.y; r.dz <- d.z;
  r

(* whether the point [t] along [r] is inside [l]'s cone (ahead of the
   light, within [falloff] of its axis), with a margin [m] in cosine *)
let inside (l : Light.t) (r : Ray.scratch) t m =
  match l.kind with
  | Light.Spot { point_at; falloff; _ } ->
      let p = Vec3.make (r.ox +. (t *. r.dx)) (r.oy +. (t *. r.dy)) (r.oz +. (t *. r.dz)) in
      let a = Vec3.normalize (Vec3.sub point_at l.position) and v = Vec3.sub p l.position in
      let len = Vec3.length v in
      len > 0. && Vec3.dot a v /. len -. Float.cos (falloff *. Float.pi /. 180.) > m
  | _ -> false

let gen =
  QCheck.Gen.(
    let v s = map3 (fun x y z -> Vec3.make x y z) (float_range (-.s) s) (float_range (-.s) s) (float_range (-.s) s) in
    tup5 (v 5.) (v 5.) (v 5.) (v 1.) (float_range 2. 60.))

let print (p, at, o, d, f) =
  Printf.sprintf "light %s at %s falloff %g, ray %s dir %s" (Vec3.to_string p) (Vec3.to_string at) f (Vec3.to_string o)
    (Vec3.to_string d)

(* the stretch holds the points inside the cone and no others: sampled
   along [-50, 50] on the ray, away from the cone's surface *)
let agrees =
  QCheck.Test.make ~name:"the cone's stretch holds exactly the points inside" ~count:3000 (QCheck.make ~print gen)
    (fun (p, at, o, d, f) ->
      QCheck.assume (Vec3.length (Vec3.sub at p) > 0.1 && Vec3.length d > 0.1);
      let l = spot p at f and r = ray o d and sp = Lit.span () in
      let hit = Lit.cone l r sp in
      for i = -500 to 500 do
        let t = float_of_int i /. 10. in
        let within = hit && t > sp.lo && t < sp.hi in
        if inside l r t 1e-6 && not within then
          QCheck.Test.fail_reportf "t = %g inside the cone, stretch %s" t
            (if hit then Printf.sprintf "[%g, %g]" sp.lo sp.hi else "none");
        if within && not (inside l r t (-1e-6)) then
          QCheck.Test.fail_reportf "t = %g outside the cone, in the stretch [%g, %g]" t sp.lo sp.hi
      done;
      true)

let close = Scn.close

(* a ray along +z through three beams from above (apex 5 units up,
   half-angle 5 degrees: each 2 x 5 tan 5 = 0.875 wide): two overlapping at
   z = 2 and 2.5, one apart at 6; lights without media_interaction and
   point lights *)
let merged () =
  let h = 5. *. Float.tan (5. *. Float.pi /. 180.) in
  let beam ?interaction z = spot ?interaction (Vec3.make 0. 5. z) (Vec3.make 0. 0. z) 5. in
  let r = ray Vec3.zero Vec3.unit_z and t = Lit.make () in
  let stretches () = List.init (Lit.count t) (fun i -> (Lit.lo t i, Lit.hi t i, Lit.is_lit t i)) in
  let check msg expected =
    let got = stretches () in
    if List.length got <> List.length expected then
      Alcotest.failf "%s: %d stretches, expected %d" msg (List.length got) (List.length expected);
    List.iteri
      (fun i ((a, b, lit), (a', b', lit')) ->
        close (Printf.sprintf "%s: stretch %d starts" msg i) a a';
        close (Printf.sprintf "%s: stretch %d ends" msg i) b b';
        if lit <> lit' then Alcotest.failf "%s: stretch %d lit %b" msg i lit')
      (List.combine expected got)
  in
  Lit.cut t [| beam 6.; beam 2.5; beam 2. |] r 10.;
  check "three beams"
    [ (0., 2. -. h, false); (2. -. h, 2.5 +. h, true); (2.5 +. h, 6. -. h, false); (6. -. h, 6. +. h, true); (6. +. h, 10., false) ];
  (* the light at index 1 lights 2.5, not 6 *)
  if not (Lit.lights t 1 2.5) then Alcotest.fail "light 1 at 2.5";
  if Lit.lights t 1 6. then Alcotest.fail "light 1 at 6";
  Lit.cut t [| beam ~interaction:false 2. |] r 10.;
  check "media_interaction off" [ (0., 10., false) ];
  Lit.cut t [| beam 2.; Light.point (Vec3.make 0. 5. 0.) Color.white |] r 10.;
  check "a point light lights all" [ (0., 10., true) ];
  (* a shadowless light is a fill light: POV-Ray's media leave it out *)
  Lit.cut t [| beam 2.; { (Light.point (Vec3.make 0. 5. 0.) Color.white) with shadowless = true } |] r 10.;
  check "a shadowless light lights nothing" [ (0., 2. -. h, false); (2. -. h, 2. +. h, true); (2. +. h, 10., false) ];
  if Lit.lights t 1 5. then Alcotest.fail "the shadowless light at 5";
  (* the ray ends inside a beam, and one beyond its end *)
  Lit.cut t [| beam 9.; beam 12. |] r 9.;
  check "cut at the ray's end" [ (0., 9. -. h, false); (9. -. h, 9., true) ];
  (* from inside a cone, looking along its axis: lit to POV-Ray's end *)
  let sp = Lit.span () in
  if not (Lit.cone (spot Vec3.zero Vec3.unit_z 10.) (ray (Vec3.make 0. 0. 1.) Vec3.unit_z) sp) then
    Alcotest.fail "along the axis";
  if not (sp.lo < 0. && sp.hi = Lit.max_distance) then Alcotest.failf "along the axis: [%g, %g]" sp.lo sp.hi;
  (* behind the light, looking away: the cone is behind the ray's origin *)
  if Lit.cone (spot Vec3.zero Vec3.unit_z 10.) (ray (Vec3.make 0. 0. (-1.)) (Vec3.make 0. 0. (-1.))) sp && sp.hi > 0. then
    Alcotest.failf "behind the light: [%g, %g]" sp.lo sp.hi;
  Lit.cut t [| spot Vec3.zero Vec3.unit_z 10. |] (ray (Vec3.make 0. 0. (-1.)) (Vec3.make 0. 0. (-1.))) 10.;
  check "behind the light" [ (0., 10., false) ]

let beam pos at falloff =
  { (Light.point pos Color.white) with kind = Light.Cylinder { point_at = at; radius = 0.; falloff; tightness = 0. } }

(* where the point [t] along [r] is from the cylinder [l]: along its axis
   (in front of its plane when positive) and from the axis *)
let from_beam (l : Light.t) (r : Ray.scratch) t =
  match l.kind with
  | Light.Cylinder { point_at; _ } ->
      let p = Vec3.make (r.ox +. (t *. r.dx)) (r.oy +. (t *. r.dy)) (r.oz +. (t *. r.dz)) in
      let a = Vec3.normalize (Vec3.sub point_at l.position) and v = Vec3.sub p l.position in
      let k = Vec3.dot a v in
      (k, Vec3.length (Vec3.sub v (Vec3.scale k a)))
  | _ -> (0., infinity)

(* POV-Ray's cylinder interval, for rays going the axis's way (the others
   it leaves out, a quirk tested below): every lit point of the ray from
   its origin on is in the stretch, and every point of the stretch in
   front of the plane is within falloff *)
let beam_agrees =
  QCheck.Test.make ~name:"the cylinder's stretch holds the lit points of the ray" ~count:3000
    (QCheck.make ~print QCheck.Gen.(map (fun (p, at, o, d, f) -> (p, at, o, d, f /. 20.)) gen))
    (fun (p, at, o, d, f) ->
      QCheck.assume (Vec3.length (Vec3.sub at p) > 0.1 && Vec3.length d > 0.1);
      let l = beam p at f and r = ray o d and sp = Lit.span () in
      let a = Vec3.normalize (Vec3.sub at p) in
      QCheck.assume (Vec3.dot a (Vec3.make r.dx r.dy r.dz) > 1e-3);
      let hit = Lit.cylinder l r sp in
      for i = 0 to 500 do
        let t = float_of_int i /. 10. in
        let within = hit && t >= sp.lo && t <= sp.hi in
        let k, d = from_beam l r t in
        if k > 1e-6 && d < f -. 1e-6 && not within then
          QCheck.Test.fail_reportf "t = %g lit, stretch %s" t
            (if hit then Printf.sprintf "[%g, %g]" sp.lo sp.hi else "none");
        if within && k > 1e-6 && d > f +. 1e-6 then
          QCheck.Test.fail_reportf "t = %g in the stretch [%g, %g], %g from the axis" t sp.lo sp.hi d
      done;
      true)

(* POV-Ray's quirks kept (media.cpp): a ray coming from behind the
   light's plane is lit from its origin on; a ray leaving the lit side
   gets an end behind its origin (so no lit stretch); a ray exactly along
   the axis gets none; the stretch across a beam, and cut to the ray *)
let beam_quirks () =
  let l = beam (Vec3.make 0. 5. 0.) Vec3.zero 1. and sp = Lit.span () and t = Lit.make () in
  (* across the beam at y = 2: x in [-1, 1] *)
  if not (Lit.cylinder l (ray (Vec3.make (-3.) 2. 0.) Vec3.unit_x) sp) then Alcotest.fail "across";
  close "across: in" 2. sp.lo;
  close "across: out" 4. sp.hi;
  (* from above the light, down and across: crosses the plane y = 5 at
     t = sqrt 2 (x = -0.5), yet lit from 0 as in POV-Ray *)
  let d = Vec3.normalize (Vec3.make 1. (-1.) 0.) in
  if not (Lit.cylinder l (ray (Vec3.make (-1.5) 6. 0.) d) sp) then Alcotest.fail "from behind";
  close "from behind: from the origin" 0. sp.lo;
  close "from behind: out at x = 1" (2.5 *. Float.sqrt 2.) sp.hi;
  (* up from inside the beam, leaving the lit side: nothing *)
  let r = ray (Vec3.make 0.2 2. 0.) (Vec3.normalize (Vec3.make 0.1 1. 0.)) in
  if Lit.cylinder l r sp && sp.hi > 0.001 then Alcotest.failf "leaving: [%g, %g]" sp.lo sp.hi;
  Lit.cut t [| l |] r 10.;
  if Lit.count t <> 1 || Lit.is_lit t 0 then Alcotest.fail "leaving: lit";
  (* down the axis: none *)
  if Lit.cylinder l (ray (Vec3.make 0. 4. 0.) (Vec3.make 0. (-1.) 0.)) sp then Alcotest.fail "along the axis";
  (* cut: lit between 2 and 4 on a ray of 3 *)
  Lit.cut t [| l |] (ray (Vec3.make (-3.) 2. 0.) Vec3.unit_x) 3.;
  if Lit.count t <> 2 || Lit.is_lit t 0 || not (Lit.is_lit t 1) then Alcotest.fail "cut: stretches";
  close "cut: unlit to 2" 2. (Lit.hi t 0);
  close "cut: lit to the ray's end" 3. (Lit.hi t 1);
  if not (Lit.lights t 0 2.5) then Alcotest.fail "light 0 at 2.5"

let tests =
  ( "lit",
    [ Alcotest.test_case "merged stretches" `Quick merged; QCheck_alcotest.to_alcotest agrees;
      QCheck_alcotest.to_alcotest beam_agrees;
      Alcotest.test_case "cylinder lights: POV-Ray's interval and its quirks" `Quick beam_quirks ] )

(* Lobes of the Monte Carlo materials: Fresnel values, and that sampling,
   evaluation and densities agree (what multiple importance sampling relies
   on). Also the POV finish -> material mapping. *)
open Camlray

let n = Vec3.unit_y
let wo = Vec3.normalize (Vec3.make 0.4 1. 0.2)

(* a fixed sequence of uniform numbers for the integrals *)
let stream seed =
  let s = Sampler.create ~seed ~pixel:0 ~sample:0 in
  fun () -> Sampler.float s

let uniform_sphere u v =
  let z = 1. -. (2. *. u) in
  let r = Float.sqrt (Float.max 0. (1. -. (z *. z))) and phi = 2. *. Float.pi *. v in
  Vec3.make (r *. Float.cos phi) z (r *. Float.sin phi)

let m lobe = { Material.lobes = [| lobe |]; emission = Color.black }

let lobes =
  [
    ("lambert", Material.Lambert (Color.gray 0.8));
    ("phong 10", Material.Phong { k = Color.gray 0.5; exponent = 10. });
    ("blinn 8", Material.Blinn { k = Color.gray 0.5; exponent = 8. });
    ("glossy 12", Material.Glossy { color = Color.gray 0.9; exponent = 12. });
  ]

let count = 200_000

(* E[weight] of sampled directions = integral of f cos over the sphere,
   the latter estimated with uniform directions; and the density
   integrates to at most 1 (exactly 1 when nothing falls below). *)
let consistency (name, lobe) =
  Alcotest.test_case (name ^ ": sample weights = integral of f cos; pdf integrates to 1") `Quick
    (fun () ->
      let mat = m lobe in
      let r = stream 1 in
      let by_sampling = ref 0. in
      for _ = 1 to count do
        match Bsdf.sample mat ~n ~wo (r ()) (r ()) (r ()) with
        | Some s -> by_sampling := !by_sampling +. s.weight.r
        | None -> ()
      done;
      let r = stream 2 in
      let by_uniform = ref 0. and pdf_int = ref 0. in
      for _ = 1 to count do
        let wi = uniform_sphere (r ()) (r ()) in
        let f = Bsdf.eval mat ~n ~wo ~wi in
        let c = Float.max 0. (Vec3.dot n wi) in
        by_uniform := !by_uniform +. (f.r *. c *. 4. *. Float.pi);
        pdf_int := !pdf_int +. (Bsdf.pdf mat ~n ~wo ~wi *. 4. *. Float.pi)
      done;
      let a = !by_sampling /. float count and b = !by_uniform /. float count in
      if Float.abs (a -. b) > 0.02 *. b then Alcotest.failf "sampled %g, integrated %g" a b;
      Alcotest.(check (float 0.02)) "pdf integral" 1. (!pdf_int /. float count))

let fresnel () =
  Alcotest.(check (float 1e-9)) "air to glass, normal" 0.04 (Bsdf.fresnel (1. /. 1.5) 1.);
  Alcotest.(check (float 1e-9)) "glass to air, normal" 0.04 (Bsdf.fresnel 1.5 1.);
  (* critical angle of glass: sin = 1/1.5 *)
  Alcotest.(check (float 0.)) "total internal reflection" 1. (Bsdf.fresnel 1.5 (Float.cos 0.75));
  Alcotest.(check (float 1e-15)) "same index" 0. (Bsdf.fresnel 1. 0.3);
  Alcotest.(check (float 1e-9)) "grazing" 1. (Bsdf.fresnel (1. /. 1.5) 0.)

let snell () =
  (* a glass lobe at 30 degrees: Snell's law and the energy split *)
  let mat = m (Material.Glass { eta = 1. /. 1.5; reflect = Color.white; transmit = Color.white }) in
  let wo = Vec3.make (Float.sin (Float.pi /. 6.)) (Float.cos (Float.pi /. 6.)) 0. in
  match Bsdf.sample mat ~n ~wo 0. 0.99 0. with
  | None -> Alcotest.fail "no sample"
  | Some s ->
      Alcotest.(check bool) "goes through" true (s.wi.y < 0.);
      Alcotest.(check (float 1e-12)) "sin t = sin i / 1.5" (0.5 /. 1.5) (-.s.wi.x)

let mapping () =
  let s =
    Helpers.compile_string
      "#version 3.7;\n\
       sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } }\n\
       sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } finish { reflection { 0.8 metallic } } }\n\
       sphere { 0, 1 pigment { rgbf <1, 0.5, 0.2, 0.6> } interior { ior 1.5 } }\n\
       sphere { 0, 1 pigment { rgb 1 } finish { emission 0.5 diffuse 0 } }\n"
  in
  let mat i =
    let o = s.objects.(i) in
    Material.of_texture o.texture o.interior Vec3.zero ~cos_o:1. ~entering:true
  in
  (match (mat 0).lobes with
  | [| Lambert a |] -> Alcotest.(check (float 1e-12)) "albedo = diffuse x pigment" 0.3 a.g
  | _ -> Alcotest.fail "default finish: one Lambertian lobe");
  (match (mat 1).lobes with
  | [| Lambert _; Mirror c |] -> Alcotest.(check (float 1e-3)) "metal: pigment-tinted" 0.4 c.g
  | _ -> Alcotest.fail "metal: Lambert + mirror");
  (match (mat 2).lobes with
  | [| Lambert a; Glass g |] ->
      Alcotest.(check (float 1e-12)) "opaque part 0.4" (0.4 *. 0.6 *. 0.5) a.g;
      Alcotest.(check (float 1e-12)) "filter tints" (0.6 *. 0.5) g.transmit.g;
      Alcotest.(check (float 1e-12)) "entering glass" (1. /. 1.5) g.eta
  | _ -> Alcotest.fail "filter + ior: Lambert + glass");
  let e = mat 3 in
  Alcotest.(check (float 0.)) "emission" 0.5 e.emission.r;
  Alcotest.(check int) "no lobes" 0 (Array.length e.lobes)

(* Shading normals: the lobes about a tilted [ns], the sides decided by
   [n]. E[weight] = the integral of f cos over the hemisphere above [n]
   (f is 0 below it); the density integrates to 1 where the lobe's
   samples are all kept (every direction a lobe sends below the surface
   is mirrored back up), to at most 1 for half-vector lobes (a half
   vector facing away from wo is dropped). *)
let tilted =
  [ ("tilted", Vec3.normalize (Vec3.make 0.6 0.8 0.)); ("steep", Vec3.normalize (Vec3.make (-0.7) 0.45 0.6)) ]

let bumped_consistency (name, lobe) (tname, ns) =
  Alcotest.test_case (Printf.sprintf "%s, %s shading normal: weights = integral of f cos, pdf" name tname) `Quick
    (fun () ->
      let mat = m lobe in
      let r = stream 3 in
      let by_sampling = ref 0. in
      for _ = 1 to count do
        match Bsdf.sample ~ns mat ~n ~wo (r ()) (r ()) (r ()) with
        | Some s ->
            if not (Vec3.dot n s.wi > 0.) then Alcotest.failf "sampled below the surface: %s" (Vec3.to_string s.wi);
            by_sampling := !by_sampling +. s.weight.r
        | None -> ()
      done;
      let r = stream 4 in
      let by_uniform = ref 0. and pdf_int = ref 0. in
      for _ = 1 to count do
        let wi = uniform_sphere (r ()) (r ()) in
        let f = Bsdf.eval ~ns mat ~n ~wo ~wi in
        let c = Float.max 0. (Vec3.dot n wi) in
        by_uniform := !by_uniform +. (f.r *. c *. 4. *. Float.pi);
        pdf_int := !pdf_int +. (Bsdf.pdf ~ns mat ~n ~wo ~wi *. 4. *. Float.pi)
      done;
      let a = !by_sampling /. float count and b = !by_uniform /. float count in
      if Sys.getenv_opt "MC_VERBOSE" <> None then Printf.printf "sampled %g integrated %g pdf %g\n" a b (!pdf_int /. float count);
      if Float.abs (a -. b) > 0.02 *. b then Alcotest.failf "sampled %g, integrated %g" a b;
      let p = !pdf_int /. float count in
      match lobe with
      | Material.Lambert _ | Material.Phong _ -> Alcotest.(check (float 0.02)) "pdf integral" 1. p
      | _ -> if p > 1.02 || p < 0.5 then Alcotest.failf "pdf integral %g" p)

(* A white Lambertian surface, however tilted its shading normal, sends
   every sample above the surface with weight exactly its albedo: no
   light is lost or made *)
let bumped_lambert () =
  let mat = m (Material.Lambert (Color.gray 0.8)) in
  let r = stream 5 in
  List.iter
    (fun (_, ns) ->
      for _ = 1 to 10_000 do
        match Bsdf.sample ~ns mat ~n ~wo (r ()) (r ()) (r ()) with
        | Some s ->
            Alcotest.(check (float 1e-12)) "weight" 0.8 s.weight.r;
            if not (Vec3.dot n s.wi > 0.) then Alcotest.fail "below the surface"
        | None -> Alcotest.fail "a Lambertian sample dropped"
      done)
    tilted

let unit_gen = QCheck.Gen.(map2 uniform_sphere (float_bound_inclusive 1.) (float_bound_inclusive 1.))

(* [n], [wo] on its side, any [ns] *)
let frame_gen =
  QCheck.Gen.(
    map3
      (fun n wo ns ->
        let wo = if Vec3.dot n wo < 0. then Vec3.neg wo else wo in
        (n, wo, ns))
      unit_gen unit_gen unit_gen)

let show (n, wo, ns) =
  Printf.sprintf "n %s wo %s ns %s" (Vec3.to_string n) (Vec3.to_string wo) (Vec3.to_string ns)

let faced n wo ns =
  let nm = Vec3.m () and om = Vec3.m () and sm = Vec3.m () in
  Vec3.load nm n;
  Vec3.load om wo;
  Vec3.load sm ns;
  Material.face sm nm om;
  Vec3.of_m sm

(* Material.face: a unit vector facing both the surface's side and the
   viewer, the same vector where it already did *)
let face_prop =
  QCheck.Test.make ~name:"face: unit, faces n and wo, unchanged where it did" ~count:2000
    (QCheck.make ~print:show frame_gen) (fun (n, wo, ns) ->
      let s = faced n wo ns in
      let e = Material.face_min -. 1e-9 in
      Float.abs (Vec3.length s -. 1.) < 1e-9
      && Vec3.dot s n >= e
      && Vec3.dot s wo >= e
      && (Vec3.dot ns n < Material.face_min || Vec3.dot ns wo < Material.face_min || s = ns))

(* No light leaks: with any shading normal (faced), a sample reflected
   by any lobe stays above the surface, one refracted by glass goes
   below it (reflect white, transmit 0.5 tell them apart) *)
let no_leak_prop =
  let mat =
    {
      Material.lobes =
        [|
          Material.Lambert (Color.gray 0.3);
          Material.Mirror (Color.gray 0.2);
          Material.Phong { k = Color.gray 0.3; exponent = 5. };
          Material.Blinn { k = Color.gray 0.3; exponent = 20. };
        |];
      emission = Color.black;
    }
  and glass = m (Material.Glass { eta = 1. /. 1.5; reflect = Color.white; transmit = Color.gray 0.5 }) in
  let u = QCheck.Gen.float_bound_exclusive 1. in
  let gen = QCheck.Gen.(pair frame_gen (triple u u u)) in
  QCheck.Test.make ~name:"shading normals: reflections stay above the surface, refractions go below"
    ~count:3000
    (QCheck.make ~print:(fun (f, _) -> show f) gen)
    (fun ((n, wo, ns), (u, v, w)) ->
      QCheck.assume (Vec3.dot n wo > 1e-6);
      let ns = faced n wo ns in
      let reflected_ok = function
        | None -> true
        | Some (s : Bsdf.sample) -> Vec3.dot n s.wi > 0. && Float.is_finite s.weight.r && s.weight.r >= 0.
      in
      reflected_ok (Bsdf.sample ~ns mat ~n ~wo u v w)
      &&
      match Bsdf.sample ~ns glass ~n ~wo u v w with
      | None -> false
      | Some s -> if s.weight.g > 0.75 then Vec3.dot n s.wi > 0. else Vec3.dot n s.wi < 0.)

let tests =
  ( "bsdf",
    Alcotest.test_case "exact Fresnel values" `Quick fresnel
    :: Alcotest.test_case "glass refracts by Snell's law" `Quick snell
    :: Alcotest.test_case "POV finishes -> materials" `Quick mapping
    :: Alcotest.test_case "white Lambert, tilted shading normals: each sample weighs its albedo" `Quick
         bumped_lambert
    :: List.map consistency lobes
    @ List.concat_map (fun l -> List.map (bumped_consistency l) tilted) lobes
    @ List.map QCheck_alcotest.to_alcotest [ face_prop; no_leak_prop ] )

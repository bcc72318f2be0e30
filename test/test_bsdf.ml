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

let tests =
  ( "bsdf",
    Alcotest.test_case "exact Fresnel values" `Quick fresnel
    :: Alcotest.test_case "glass refracts by Snell's law" `Quick snell
    :: Alcotest.test_case "POV finishes -> materials" `Quick mapping
    :: List.map consistency lobes )

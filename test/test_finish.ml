(* POV-Ray's finish formulas that both modes use: the dielectric Fresnel
   reflectance and the metallic tint, against known values and against
   the Monte Carlo BSDF's independent form of the Fresnel equations. *)
open Camlray

let fresnel_known () =
  Alcotest.(check (float 1e-12)) "air to glass, head-on: ((1.5-1)/(1.5+1))^2" 0.04 (Finish.fresnel 1.5 1.);
  Alcotest.(check (float 1e-12)) "glass to air, head-on" 0.04 (Finish.fresnel (1. /. 1.5) 1.);
  Alcotest.(check (float 0.)) "past the critical angle" 1. (Finish.fresnel (1. /. 1.5) (Float.cos 0.75));
  Alcotest.(check (float 1e-12)) "same index: nothing reflected" 0. (Finish.fresnel 1. 0.4);
  Alcotest.(check (float 1e-9)) "grazing: all reflected" 1. (Finish.fresnel 1.5 1e-12)

(* Finish.fresnel takes n = n_t / n_i, Bsdf.fresnel eta = n_i / n_t: the
   same reflectance written two ways *)
let fresnel_agrees =
  QCheck.Test.make ~count:500 ~name:"POV-Ray's Fresnel formula equals the Fresnel equations"
    QCheck.(pair (float_range 0.4 2.5) (float_range 0.001 1.))
    (fun (n, c) ->
      let a = Finish.fresnel n c and b = Bsdf.fresnel (1. /. n) c in
      Float.abs (a -. b) <= 1e-12 *. Float.max 1. (Float.abs b))

let metallic () =
  Alcotest.(check (float 0.)) "no metallic: no tint" 0. (Finish.metallic_k 0. 0.7);
  Alcotest.(check (float 1e-6)) "head-on: the full amount" 0.8 (Finish.metallic_k 0.8 1.);
  Alcotest.(check (float 1e-6)) "grazing: none" 0. (Finish.metallic_k 0.8 0.);
  (* the tint moves a channel toward the pigment's by k *)
  Alcotest.(check (float 1e-12)) "tint" 0.6 (Finish.tint 1. 0.5 0.2);
  Alcotest.(check (float 0.)) "no metallic: factor 1" 1. (Finish.tint 0. 0.5 0.2);
  let rec falls c prev = c < 0. || (let k = Finish.metallic_k 1. c in k <= prev +. 1e-12 && falls (c -. 0.01) k) in
  Alcotest.(check bool) "the tint fades from head-on to grazing" true (falls 1. infinity)

let tests =
  ( "finish",
    [ Alcotest.test_case "Fresnel reflectance, known values" `Quick fresnel_known;
      QCheck_alcotest.to_alcotest fresnel_agrees;
      Alcotest.test_case "metallic tint" `Quick metallic ] )

(* Algebraic's expansion of the polynomial along a ray against the
   term-by-term one it replaced (Before), and its first hit against the
   one before: the same bits, for random surfaces and for those of
   scenes/whitted-extra/algebraic.pov, on random rays and rays grazing
   them. *)
open Camlray

let same_bits a b = Int64.equal (Int64.bits_of_float a) (Int64.bits_of_float b)
let show a = Printf.sprintf "%h (%.17g)" a a

let show_poly c =
  String.concat " " (List.init (Float.Array.length c) (fun m -> Printf.sprintf "%h" (Float.Array.get c m)))

let random_order =
  let open QCheck.Gen in
  let* order = oneof_weighted [ (10, int_range 1 6); (1, return 15) ] in
  let+ coef =
    array_size (return (Algebraic.terms order))
      (oneof_weighted [ (3, return 0.); (2, float_range (-3.) 3.); (1, oneof_list [ 1.; -1.; 2.; 0.5 ]) ])
  in
  (order, coef)

(* line components with zeros of both signs, as axis-aligned rays have *)
let component =
  QCheck.Gen.(oneof_weighted [ (6, float_range (-3.) 3.); (1, return 0.); (1, return (-0.)); (1, return 1.) ])

let along_prop =
  QCheck.Test.make ~name:"Algebraic.along: the term-by-term expansion, to the bit" ~count:1000
    QCheck.(make ~print:(fun ((order, coef), q) ->
                Printf.sprintf "order %d [%s] line %s" order
                  (String.concat "; " (Array.to_list (Array.map string_of_float coef)))
                  (String.concat " " (List.map (Printf.sprintf "%h") q)))
              Gen.(pair random_order (list_size (return 6) component)))
    (fun ((order, coef), q) ->
      match q with
      | [ qx; qy; qz; nx; ny; nz ] ->
          let a = Algebraic.make order coef in
          let got = Algebraic.along a qx qy qz nx ny nz and want = Before.along order coef qx qy qz nx ny nz in
          (Float.Array.length got = order + 1
          && List.for_all
               (fun m -> same_bits (Float.Array.get got m) (Float.Array.get want m))
               (List.init (order + 1) Fun.id))
          || QCheck.Test.fail_reportf "got %s, want %s" (show_poly got) (show_poly want)
      | _ -> assert false)

(* The shapes of scenes/whitted-extra/algebraic.pov and others of
   Geom_gen, a random one of order up to 6, hit by random rays and by rays
   grazing them (tangent to a torus, a sphere or a saddle at a distance
   moved by a little) *)
let torus =
  ( 4,
    [| 1.; 0.; 0.; 0.; 2.; 0.; 0.; 2.; 0.; -2.245; 0.; 0.; 0.; 0.; 0.; 0.; 0.; 0.; 0.; 0.;
       1.; 0.; 0.; 2.; 0.; 1.755; 0.; 0.; 0.; 0.; 1.; 0.; -2.245; 0.; 0.77000625 |] )
let lemniscate = (4, Array.init 35 (fun i -> match i with 0 -> 1. | 9 -> -1. | 25 -> 1. | 32 -> 1. | _ -> 0.))
let saddle = (3, Array.init 20 (fun i -> match i with 0 -> -0.3 | 7 -> 0.9 | 15 -> 1. | _ -> 0.))
let sphere = (2, [| 1.; 0.; 0.; 0.; 1.; 0.; 0.; 1.; 0.; -1. |])
let hyperboloid = (2, [| 1.; 0.; 0.; 0.; -1.; 0.; 0.; 1.; 0.; -0.15 |])

let gshape =
  QCheck.Gen.(oneof_weighted
                [ (2, return torus); (1, return lemniscate); (1, return saddle); (1, return sphere);
                  (1, return hyperboloid); (1, random_order) ])

let gray =
  let open QCheck.Gen in
  let nudge = oneof_list [ 0.; 1e-15; -1e-15; 1e-12; -1e-12; 1e-9; -1e-9; 1e-6; -1e-6 ] in
  oneof
    [
      list_size (return 6) (float_range (-4.) 4.);
      list_size (return 6) component;
      (* along x, past the torus's outer rim or over its top, past the
         sphere, along the saddle's flat line *)
      map2 (fun e z -> [ -5.; 0.; z +. e; 1.; 0.; 0. ]) nudge (oneof_list [ 1.35; 0.65; 1. ]);
      map2 (fun e y -> [ -5.; y +. e; 1.; 1.; 0.; 0. ]) nudge (oneof_list [ 0.35; 0.; -0.35 ]);
      map2 (fun e d -> [ 0.2; 3.; -5.; 0.; d +. e; 1. ]) nudge (oneof_list [ -0.5; -0.6; -0.7 ]);
    ]

let first_hit_prop =
  QCheck.Test.make ~name:"Algebraic.first_hit: the hit found before, to the bit" ~count:10000
    QCheck.(make ~print:(fun ((order, coef), (ray, tmin)) ->
                Printf.sprintf "order %d [%s] ray %s tmin %g" order
                  (String.concat "; " (Array.to_list (Array.map string_of_float coef)))
                  (String.concat " " (List.map (Printf.sprintf "%h") ray)) tmin)
              Gen.(pair gshape (pair gray (oneof_list [ 0.; 1e-3; 1.; 4. ]))))
    (fun ((order, coef), (ray, tmin)) ->
      match ray with
      | [ ox; oy; oz; dx; dy; dz ] ->
          QCheck.assume (dx <> 0. || dy <> 0. || dz <> 0.);
          let a = Algebraic.make order coef in
          let got = Algebraic.first_hit a ox oy oz dx dy dz tmin
          and want = Before.first_hit order coef ox oy oz dx dy dz tmin in
          same_bits got want || QCheck.Test.fail_reportf "got %s, want %s" (show got) (show want)
      | _ -> assert false)

let tests = ("algebraic", List.map QCheck_alcotest.to_alcotest [ along_prop; first_hit_prop ])

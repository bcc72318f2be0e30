(* Poly's search for a polynomial's first root against the search it
   replaced (Before): ruling a root out without finding every critical
   point, and finding critical points only up to the first root, must give
   the same bits, on polynomials made to be hard (near-double roots,
   double roots lifted off the axis by as little as rounding, tiny leading
   terms). *)
open Camlray

let same_bits a b = Int64.equal (Int64.bits_of_float a) (Int64.bits_of_float b)
let show a = Printf.sprintf "%h (%.17g)" a a

(* [k] times the product of (t - r) over the roots *)
let from_roots k rs =
  List.fold_left
    (fun c r ->
      let n = Array.length c in
      Array.init (n + 1) (fun m -> (if m > 0 then c.(m - 1) else 0.) -. if m < n then r *. c.(m) else 0.))
    [| k |] rs

(* Made to be hard for a search that rules roots out: roots known, double
   ones, and a constant term moved by a little (a double root split in
   two close ones or lifted off the axis by as little as rounding);
   random coefficients, some zero, some leading terms tiny *)
let gpoly =
  let open QCheck.Gen in
  let nudge =
    oneof_list [ 0.; 1e-300; 1e-16; -1e-16; 1e-13; -1e-13; 1e-10; -1e-10; 1e-7; -1e-7; 1e-4; -1e-4; 0.1; -0.1 ]
  in
  let roots = list_size (int_range 1 6) (float_range (-5.) 5.) in
  let scale = map (fun k -> if Float.abs k < 0.01 then 1. else k) (float_range (-3.) 3.) in
  oneof
    [
      map3 (fun k rs e -> let c = from_roots k rs in c.(0) <- c.(0) +. (e *. Float.abs k); c) scale roots nudge;
      (* a double root, and others *)
      map3
        (fun k (a, rs) e -> let c = from_roots k (a :: a :: rs) in c.(0) <- c.(0) +. (e *. Float.abs k); c)
        scale (pair (float_range (-3.) 3.) (list_size (int_range 0 2) (float_range (-5.) 5.))) nudge;
      (* a double root times a factor without real roots (a ray grazing a
         torus) *)
      map3
        (fun k (a, (p, q)) e ->
          let c = from_roots k [ a; a ] in
          let c = Array.init 5 (fun m ->
            let at i = if i >= 0 && i < 3 then c.(i) else 0. in
            (* c * (t^2 + p t + q) *)
            at (m - 2) +. (p *. at (m - 1)) +. (q *. at m)) in
          c.(0) <- c.(0) +. (e *. Float.abs k);
          c)
        scale (pair (float_range (-3.) 3.) (pair (float_range (-2.) 2.) (float_range 1.01 4.))) nudge;
      map2
        (fun cs lead -> let n = Array.length cs in Array.init (n + 1) (fun m -> if m < n then cs.(m) else lead))
        (array_size (int_range 1 6) (oneof [ return 0.; float_range (-5.) 5. ]))
        (oneof_list [ 1.; -2.; 1e-17; 1e-25; 0.5 ]);
    ]

let gwindow =
  let open QCheck.Gen in
  pair (float_range (-6.) 6.) (oneof [ return infinity; float_range 0. 10. ])

let first_root_prop =
  QCheck.Test.make ~name:"Poly.first_root_in: the root the search before found, to the bit" ~count:20000
    QCheck.(make ~print:(fun (c, (lo, len)) ->
                Printf.sprintf "[%s] lo %h len %h"
                  (String.concat "; " (Array.to_list (Array.map (Printf.sprintf "%h") c))) lo len)
              Gen.(pair gpoly gwindow))
    (fun (c, (lo, len)) ->
      let degree = Array.length c - 1 in
      let eqn = Float.Array.of_list (Array.to_list c) and hi = lo +. len in
      let sc = Poly.scratch 8 in
      let got = if Poly.first_root_in sc eqn degree lo hi then Some (Poly.root sc) else None in
      match (got, Before.first_root_in eqn degree lo hi) with
      | None, None -> true
      | Some a, Some b when same_bits a b -> true
      | Some a, None -> QCheck.Test.fail_reportf "found %s, before none" (show a)
      | None, Some b -> QCheck.Test.fail_reportf "found none, before %s" (show b)
      | Some a, Some b -> QCheck.Test.fail_reportf "found %s, before %s" (show a) (show b))

(* Stopping at a bound moves no root: the first root below the stop is
   the first root, to the bit; none is found when the first root is at
   or past the stop *)
let below_prop =
  QCheck.Test.make ~name:"Poly.first_root_below: first_root's root, or none past the stop" ~count:20000
    QCheck.(make ~print:(fun (c, (lo, stop)) ->
                Printf.sprintf "[%s] lo %h stop %h"
                  (String.concat "; " (Array.to_list (Array.map (Printf.sprintf "%h") c))) lo stop)
              Gen.(pair gpoly (pair (float_range (-6.) 6.) (float_range (-6.) 8.))))
    (fun (c, (lo, stop)) ->
      let degree = Array.length c - 1 in
      let eqn = Float.Array.of_list (Array.to_list c) in
      let sc = Poly.scratch 8 in
      let all = if Poly.first_root sc eqn degree lo then Some (Poly.root sc) else None in
      let got = if Poly.first_root_below sc eqn degree lo stop then Some (Poly.root sc) else None in
      match (all, got) with
      | None, None -> true
      | Some a, None when a >= stop -> true
      | Some a, Some b when same_bits a b && a < stop -> true
      | Some a, None -> QCheck.Test.fail_reportf "none found, first_root %s below the stop" (show a)
      | None, Some b -> QCheck.Test.fail_reportf "found %s, first_root none" (show b)
      | Some a, Some b -> QCheck.Test.fail_reportf "found %s, first_root %s" (show b) (show a))

(* A window that ends before the roots' bound: roots below minus its end
   are still in it (the window was once clipped to [-hi, hi]) *)
let windows =
  Alcotest.test_case "first_root_in: a window below minus its end" `Quick (fun () ->
      let sc = Poly.scratch 8 in
      List.iter
        (fun (name, c, lo, hi, want) ->
          let eqn = Float.Array.of_list c in
          let got = if Poly.first_root_in sc eqn (List.length c - 1) lo hi then Poly.root sc else nan in
          Alcotest.(check (float 1e-12)) name want got)
        [ ("line t + 3 in (-5, 1)", [ 3.; 1. ], -5., 1., -3.);
          ("(t + 3)(t - 2) in (-5, 1)", [ -6.; 1.; 1. ], -5., 1., -3.);
          ("(t + 3)(t + 2)(t - 1) in (-4, 0.5)", [ -6.; 1.; 4.; 1. ], -4., 0.5, -3.);
          ("(t + 4)(t + 1)(t - 1)(t - 2) in (-5, 0.2)", [ 8.; -2.; -9.; 2.; 1. ], -5., 0.2, -4.) ];
      let found = Float.Array.make 3 0. in
      let n = Poly.cubic_roots_in found 1. 4. 1. (-6.) (-4.) 0.5 in
      Alcotest.(check int) "cubic_roots_in: both roots below" 2 n;
      Alcotest.(check (float 1e-12)) "the first" (-3.) (Float.Array.get found 0);
      Alcotest.(check (float 1e-12)) "the second" (-2.) (Float.Array.get found 1))

let tests = ("poly", windows :: List.map QCheck_alcotest.to_alcotest [ first_root_prop; below_prop ])

(* The counter-based sampler: pure dimensions, distinct streams, uniform
   numbers. *)
open Camlray

let pure () =
  let s = Sampler.create ~seed:1 ~pixel:5 ~sample:3 in
  let a = Sampler.get s 7 in
  let seq = List.init 10 (fun _ -> Sampler.float s) in
  Alcotest.(check (float 0.)) "get is pure" a (Sampler.get s 7);
  Alcotest.(check (float 0.)) "float walks the dimensions" (List.nth seq 7) a

let distinct () =
  (* neighbouring pixels, samples and seeds never share a stream *)
  let first seed pixel sample = Sampler.get (Sampler.create ~seed ~pixel ~sample) 0 in
  let seen = Hashtbl.create 4096 in
  for seed = 0 to 3 do
    for pixel = 0 to 31 do
      for sample = 0 to 31 do
        let v = first seed pixel sample in
        if Hashtbl.mem seen v then Alcotest.failf "collision at %d %d %d" seed pixel sample;
        Hashtbl.add seen v ()
      done
    done
  done

let uniform () =
  (* mean, variance and a 16-bin histogram over 64k numbers *)
  let n = 65536 in
  let bins = Array.make 16 0 and s = ref 0. and s2 = ref 0. in
  for k = 0 to n - 1 do
    let v = Sampler.get (Sampler.create ~seed:9 ~pixel:(k / 64) ~sample:(k mod 64)) (k mod 5) in
    if v < 0. || v >= 1. then Alcotest.failf "out of range: %g" v;
    s := !s +. v;
    s2 := !s2 +. (v *. v);
    bins.(int_of_float (v *. 16.)) <- bins.(int_of_float (v *. 16.)) + 1
  done;
  let m = !s /. float n in
  Alcotest.(check (float 0.005)) "mean 1/2" 0.5 m;
  Alcotest.(check (float 0.005)) "variance 1/12" (1. /. 12.) ((!s2 /. float n) -. (m *. m));
  (* chi-square with 15 degrees of freedom: 99.9% quantile 37.7 *)
  let e = float n /. 16. in
  let chi = Array.fold_left (fun a c -> a +. (((float c -. e) ** 2.) /. e)) 0. bins in
  if chi > 37.7 then Alcotest.failf "chi-square %g" chi

let tests =
  ( "sampler",
    [
      Alcotest.test_case "dimensions are pure; float walks them" `Quick pure;
      Alcotest.test_case "distinct streams for seeds, pixels, samples" `Quick distinct;
      Alcotest.test_case "uniform: mean, variance, chi-square" `Quick uniform;
    ] )

(* noise_bench MODE N: N evaluations of MODE (POV-Ray's noise: pov1,
   pov2, pov3 for the generators, povd for DNoise, povturb7 and povdturb7
   for 7-octave Turbulence and DTurbulence) at N pseudo-random points in
   [-40, 40]^3; prints a checksum so the work is not dropped. Instructions
   per evaluation: callgrind's count for N minus its count for 0, over N. *)
open Camlray

let () =
  let mode = Sys.argv.(1) and n = int_of_string Sys.argv.(2) in
  let pts = Float.Array.make (3 * 4096) 0. in
  let s = ref 0x1234567 in
  for i = 0 to (3 * 4096) - 1 do
    s := (!s * 1103515245 + 12345) land 0x3FFFFFFF;
    Float.Array.set pts i ((float_of_int !s /. float_of_int 0x3FFFFFFF *. 80.) -. 40.)
  done;
  let acc = ref 0. in
  let p = Vec3.m () and out = Vec3.m () in
  let g i = Float.Array.unsafe_get pts i in
  (match mode with
  | "pov1" | "pov2" | "pov3" ->
      let gen = Char.code mode.[3] - Char.code '0' in
      for i = 0 to n - 1 do
        let k = 3 * (i land 4095) in
        acc := !acc +. Noise.noise gen (g k) (g (k + 1)) (g (k + 2))
      done
  | "povd" ->
      for i = 0 to n - 1 do
        let k = 3 * (i land 4095) in
        Noise.dnoise (g k) (g (k + 1)) (g (k + 2)) out;
        acc := !acc +. out.mx +. out.my +. out.mz
      done
  | "povturb7" ->
      for i = 0 to n - 1 do
        let k = 3 * (i land 4095) in
        acc := !acc +. Noise.turbulence 2 ~octaves:7 ~omega:0.5 ~lambda:2. (g k) (g (k + 1)) (g (k + 2))
      done
  | "povdturb7" ->
      for i = 0 to n - 1 do
        let k = 3 * (i land 4095) in
        Vec3.set p (g k) (g (k + 1)) (g (k + 2));
        Noise.dturbulence ~octaves:7 ~omega:0.5 ~lambda:2. p out;
        acc := !acc +. out.mx +. out.my +. out.mz
      done
  | _ -> failwith "mode");
  Printf.printf "%s %d %.17g\n" mode n !acc

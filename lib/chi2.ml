(* Regularized incomplete gamma functions by the textbook series (x below
   a + 1) and Lentz's continued fraction (above), with a Lanczos log-gamma;
   the quantile by bisection, which is plenty fast for the few hundred
   thresholds a scene needs once. *)

(* Lanczos (g = 7, 9 terms) log-gamma for a > 0 *)
let lanczos =
  [| 0.99999999999980993; 676.5203681218851; -1259.1392167224028; 771.32342877765313;
     -176.61502916214059; 12.507343278686905; -0.13857109526572012;
     9.9843695780195716e-6; 1.5056327351493116e-7 |]

let rec log_gamma a =
  if a < 0.5 then
    (* reflection *)
    Float.log (Float.pi /. Float.abs (Float.sin (Float.pi *. a))) -. log_gamma (1. -. a)
  else begin
    let a = a -. 1. in
    let s = ref lanczos.(0) in
    for i = 1 to 8 do
      s := !s +. (lanczos.(i) /. (a +. float_of_int i))
    done;
    let t = a +. 7.5 in
    (0.5 *. Float.log (2. *. Float.pi)) +. ((a +. 0.5) *. Float.log t) -. t +. Float.log !s
  end

(* P(a, x) for x < a + 1 *)
let lower_series a x =
  let sum = ref (1. /. a) and term = ref (1. /. a) and n = ref 1 in
  while Float.abs !term > Float.abs !sum *. 1e-17 && !n < 10_000 do
    term := !term *. x /. (a +. float_of_int !n);
    sum := !sum +. !term;
    incr n
  done;
  !sum *. Float.exp (-.x +. (a *. Float.log x) -. log_gamma a)

(* Q(a, x) for x >= a + 1 *)
let upper_fraction a x =
  let tiny = 1e-300 in
  let b = ref (x +. 1. -. a) in
  let c = ref (1. /. tiny) and d = ref (1. /. !b) in
  let h = ref !d and n = ref 1 and fin = ref false in
  while (not !fin) && !n < 10_000 do
    let an = -.float_of_int !n *. (float_of_int !n -. a) in
    b := !b +. 2.;
    d := (an *. !d) +. !b;
    if Float.abs !d < tiny then d := tiny;
    c := !b +. (an /. !c);
    if Float.abs !c < tiny then c := tiny;
    d := 1. /. !d;
    let delta = !d *. !c in
    h := !h *. delta;
    if Float.abs (delta -. 1.) < 1e-16 then fin := true;
    incr n
  done;
  Float.exp (-.x +. (a *. Float.log x) -. log_gamma a) *. !h

let upper_tail ~df x =
  if x <= 0. then 1.
  else
    let a = 0.5 *. df and x = 0.5 *. x in
    if x < a +. 1. then 1. -. lower_series a x else upper_fraction a x

let quantile_upper ~df p =
  if p >= 1. then 0.
  else if p <= 0. then infinity
  else begin
    (* upper_tail falls from 1 to 0: find a bracket, then halve it *)
    let hi = ref (Float.max 1. df) in
    while upper_tail ~df !hi > p do
      hi := 2. *. !hi
    done;
    let lo = ref 0. and hi = ref !hi and mid = ref (0.5 *. !hi) in
    (* until the bracket is two neighbouring floats *)
    while !mid > !lo && !mid < !hi do
      if upper_tail ~df !mid > p then lo := !mid else hi := !mid;
      mid := 0.5 *. (!lo +. !hi)
    done;
    !mid
  end

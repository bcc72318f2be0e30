type t = { pigments : Pigment.t list }

let none = { pigments = [] }
let is_empty s = s.pigments = []
let transform tr s = { pigments = List.map (Pigment.transform tr) s.pigments }

(* Layers over the background, top down, in scalars (the same
   arithmetic as with colour records): what each layer lets through
   weighs those below; nothing below a layer that lets nothing through. *)
let pig_key = Scratch.key Pigment.out

let eval_into s ~(background : Color.t) (dir : Vec3.m) (out : Color.acc) =
  let c = Scratch.get pig_key in
  let ar = ref 0. and ag = ref 0. and ab = ref 0. in
  let wr = ref 1. and wg = ref 1. and wb = ref 1. in
  let rest = ref s.pigments and go = ref true in
  while !go do
    match !rest with
    | [] ->
        let bg = background in
        ar := !ar +. (!wr *. bg.r);
        ag := !ag +. (!wg *. bg.g);
        ab := !ab +. (!wb *. bg.b);
        go := false
    | p :: tl ->
        Pigment.into p dir c;
        let alpha = 1. -. c.filter -. c.transmit in
        ar := !ar +. (alpha *. (!wr *. c.r));
        ag := !ag +. (alpha *. (!wg *. c.g));
        ab := !ab +. (alpha *. (!wb *. c.b));
        wr := !wr *. ((c.filter *. c.r) +. c.transmit);
        wg := !wg *. ((c.filter *. c.g) +. c.transmit);
        wb := !wb *. ((c.filter *. c.b) +. c.transmit);
        if !wr = 0. && !wg = 0. && !wb = 0. then go := false else rest := tl
  done;
  Color.acc_set out !ar !ag !ab

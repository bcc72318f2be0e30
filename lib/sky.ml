type t = { pigments : Pigment.t list; legacy : bool }

let none = { pigments = []; legacy = false }
let is_empty s = s.pigments = []
let transform tr s = { s with pigments = List.map (Pigment.transform tr) s.pigments }

(* Layers over the background, top down, in scalars (the same
   arithmetic as with colour records): what each layer lets through
   weighs those below; nothing below a layer that lets nothing through. *)
let pig_key = Scratch.key Pigment.out

(* POV-Ray 3.6's rule (scenes before #version 3.7): a layer weighs by the
   filter and transmit of the layers above, multiplied, as one number
   (|filter product| + |transmit product|), not by their colour; the
   background then shows through the colour of their filter product and
   their transmit product *)
let eval_legacy_into s ~(background : Color.t) (dir : Vec3.m) (out : Color.acc) =
  let c = Scratch.get pig_key in
  let ar = ref 0. and ag = ref 0. and ab = ref 0. in
  let fr = ref 1. and fg = ref 1. and fb = ref 1. and ff = ref 1. and ft = ref 1. and trans = ref 1. in
  (* a loop, not List.iter: float refs a closure captures are boxed *)
  let rest = ref s.pigments and go = ref true in
  while !go do
    match !rest with
    | [] -> go := false
    | p :: tl ->
        Pigment.into p dir c;
        let att = !trans *. (1. -. c.filter -. c.transmit) in
        ar := !ar +. (c.r *. att);
        ag := !ag +. (c.g *. att);
        ab := !ab +. (c.b *. att);
        fr := !fr *. c.r;
        fg := !fg *. c.g;
        fb := !fb *. c.b;
        ff := !ff *. c.filter;
        ft := !ft *. c.transmit;
        trans := Float.abs !ff +. Float.abs !ft;
        rest := tl
  done;
  Color.acc_set out
    (!ar +. (background.r *. ((!fr *. !ff) +. !ft)))
    (!ag +. (background.g *. ((!fg *. !ff) +. !ft)))
    (!ab +. (background.b *. ((!fb *. !ff) +. !ft)))

let eval_into s ~(background : Color.t) (dir : Vec3.m) (out : Color.acc) =
  if s.legacy then eval_legacy_into s ~background dir out else
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

(* User-defined functions: POV-Ray's function { ... } bodies, compiled
   once into OCaml closures working in a frame of float slots (the
   parameters, then the values of sub-expressions, then the frames of the
   functions called), and the vector functions. *)
open Camlray

type code = float array -> int -> unit

type vector =
  | Transform of Transform.t  (** the point moved by it: x, y, z *)
  | Spline of Spline.fn  (** its value at the parameter *)
  | Colour of Pigment.t  (** a pigment function: red, green, blue, filter, transmit *)

type t = {
  params : string array;
  frame : int;
  out : int;
  run : code;
  unsupported : string option;
  vector : vector option;
  source : string option;
}

let nothing : code = fun _ _ -> ()

let make ?source ~params ~frame ~out ~unsupported run =
  if frame < Array.length params || out < 0 || out >= max frame 1 then invalid_arg "Fn.make: bad frame";
  { params; frame; out; run; unsupported; vector = None; source }

let vector_fn params v = { params; frame = Array.length params; out = 0; run = nothing; unsupported = None; vector = Some v; source = None }

let of_transform tr = vector_fn [| "x"; "y"; "z" |] (Transform tr)
let of_spline s = vector_fn [| "t" |] (Spline (Spline.prepare s))
let of_pigment p = vector_fn [| "x"; "y"; "z" |] (Colour p)
let is_vector f = f.vector <> None
let frame f = f.frame
let out f = f.out
let run f = f.run
let arity f = Array.length f.params
let params f = Array.to_list f.params
let unsupported f = f.unsupported
let source f = f.source

(* POV-Ray's members of a vector function's value; gray weighs the
   channels as POV-Ray's colours do *)
let gray = 5

let member = function
  | "x" | "u" | "red" -> Some 0
  | "y" | "v" | "green" -> Some 1
  | "z" | "blue" -> Some 2
  | "t" | "filter" -> Some 3
  | "transmit" -> Some 4
  | "gray" | "grey" -> Some gray
  | _ -> None

let[@inline] gray_of r g b = (0.297 *. r) +. (0.589 *. g) +. (0.114 *. b)

let check_args loc f n =
  let k = Array.length f.params in
  if n <> k then Diag.error loc "this function takes %d argument%s, got %d" k (if k = 1 then "" else "s") n

(* the per-domain point and colour of one call of a pigment function *)
type pig_work = { p : Vec3.m; o : Pigment.out }

let member_code loc f m ~args ~out =
  check_args loc f (Array.length args);
  match f.vector with
  | None -> Diag.error loc "this function returns a float: it has no members"
  | Some (Transform tr) ->
      if m <> gray && m >= 3 then Diag.error loc "this function's value has 3 components: this member does not exist";
      (* each domain its own point and image, as for a pigment function *)
      let key = Scratch.key (fun () -> (Vec3.m (), Vec3.m ())) in
      let ax = args.(0) and ay = args.(1) and az = args.(2) in
      fun s b ->
        let q, o = Scratch.get key in
        Vec3.set q (Array.unsafe_get s (b + ax)) (Array.unsafe_get s (b + ay)) (Array.unsafe_get s (b + az));
        Transform.point_m tr q o;
        let i = b + out in
        (match m with
        | 0 -> Array.unsafe_set s i o.mx
        | 1 -> Array.unsafe_set s i o.my
        | 2 -> Array.unsafe_set s i o.mz
        | _ -> Array.unsafe_set s i (gray_of o.mx o.my o.mz))
  | Some (Spline sp) ->
      let a = args.(0) in
      if m <> gray then fun s b -> Spline.component_into sp s (b + a) m s (b + out)
      else
        (* the three channels in the domain's own slots *)
        let key = Scratch.key (fun () -> Array.make 3 0.) in
        fun s b ->
          let w = Scratch.get key in
          Spline.component_into sp s (b + a) 0 w 0;
          Spline.component_into sp s (b + a) 1 w 1;
          Spline.component_into sp s (b + a) 2 w 2;
          Array.unsafe_set s (b + out) (gray_of (Array.unsafe_get w 0) (Array.unsafe_get w 1) (Array.unsafe_get w 2))
  | Some (Colour pig) ->
      (match m with
      | 0 | 1 | 2 | 3 | 4 -> ()
      | m when m = gray -> ()
      | _ -> Diag.error loc "a pigment function's value has no such member");
      (* each domain its own point and colour; this call cannot run again
         while it runs (a pigment cannot use a function defined after it);
         Pigment.into starts below the scratch colours the maps being
         evaluated hold *)
      let key = Scratch.key (fun () -> { p = Vec3.m (); o = Pigment.out () }) in
      let ax = args.(0) and ay = args.(1) and az = args.(2) in
      fun s b ->
        let w = Scratch.get key in
        Vec3.set w.p (Array.unsafe_get s (b + ax)) (Array.unsafe_get s (b + ay)) (Array.unsafe_get s (b + az));
        Pigment.into pig w.p w.o;
        let o = w.o and i = b + out in
        (* each case stores its value (a value joined from the cases
           would be boxed) *)
        match m with
        | 0 -> Array.unsafe_set s i o.r
        | 1 -> Array.unsafe_set s i o.g
        | 2 -> Array.unsafe_set s i o.b
        | 3 -> Array.unsafe_set s i o.filter
        | 4 -> Array.unsafe_set s i o.transmit
        | _ -> Array.unsafe_set s i (gray_of o.r o.g o.b)

let frame_of loc f args =
  (match f.unsupported with Some u -> Diag.error loc "%s" u | None -> ());
  check_args loc f (List.length args);
  let s = Array.make (max f.frame 1) 0. in
  List.iteri (fun i a -> s.(i) <- a) args;
  s

let call loc f args =
  if f.vector <> None then Diag.error loc "this is a vector function: its value is a vector";
  let s = frame_of loc f args in
  f.run s 0;
  s.(f.out)

let call_vector loc f args =
  match f.vector with
  | Some (Transform tr) ->
      let a = frame_of loc f args in
      let p = Transform.point tr (Vec3.make a.(0) a.(1) a.(2)) in
      [| p.x; p.y; p.z |]
  | Some (Spline sp) -> Spline.value sp (frame_of loc f args).(0)
  | Some (Colour p) -> (
      match args with
      | [ x; y; z ] ->
          let c = Pigment.eval p (Vec3.make x y z) in
          [| c.c.r; c.c.g; c.c.b; c.filter; c.transmit |]
      | _ -> check_args loc f (List.length args); [||])
  | None -> Diag.error loc "this is a float function, not a vector function"

let eval f args =
  (match f.unsupported with Some u -> invalid_arg u | None -> ());
  if f.vector <> None then invalid_arg "Fn.eval: a vector function";
  if Array.length args <> Array.length f.params then invalid_arg "Fn.eval: wrong number of arguments";
  let s = Array.make (max f.frame 1) 0. in
  Array.blit args 0 s 0 (Array.length args);
  f.run s 0;
  s.(f.out)

let eval3 f =
  (match f.unsupported with Some u -> invalid_arg u | None -> ());
  if f.vector <> None then invalid_arg "Fn.eval3: a vector function";
  if Array.length f.params <> 3 then invalid_arg "Fn.eval3: the function does not take 3 arguments";
  let n = f.frame and code = f.run and out = f.out in
  fun x y z ->
    let s = Array.make n 0. in
    s.(0) <- x;
    s.(1) <- y;
    s.(2) <- z;
    code s 0;
    s.(out)

let pattern loc f =
  (match f.unsupported with Some u -> Diag.error loc "%s" u | None -> ());
  if f.vector <> None then
    Diag.error loc "a vector function cannot be a pattern: take one of its components (F(x, y, z).x)";
  if Array.length f.params <> 3 then
    Diag.error loc "a function used as a pattern takes 3 parameters (x, y, z), this one takes %d"
      (Array.length f.params);
  let run = f.run in
  Pattern.fn ~slots:f.frame ~result:f.out (fun s -> run s 0)

(* pigment_pattern { P }: the grey of P's colour, clipped to [0, 1]
   (above 1 POV-Ray gives 1 - 1e-5: measured, rgb 2 gives 0.99999) *)
let pigment_pattern loc p =
  let code = member_code loc (of_pigment p) gray ~args:[| 0; 1; 2 |] ~out:3 in
  Pattern.fn ~slots:4 ~result:3 (fun s ->
      code s 0;
      let v = Array.unsafe_get s 3 in
      Array.unsafe_set s 3 (if v < 0. then 0. else if v > 1. then 1. -. 1e-5 else v))

(* function { pattern { P } }: each domain its own point and work *)
let of_pattern (p : Pattern.t) xform =
  let key = Scratch.key (fun () -> (Vec3.m (), Pattern.work ())) in
  make ~source:"pattern" ~params:[| "x"; "y"; "z" |] ~frame:4 ~out:3 ~unsupported:None (fun s b ->
      let q, w = Scratch.get key in
      Vec3.set q (Array.unsafe_get s b) (Array.unsafe_get s (b + 1)) (Array.unsafe_get s (b + 2));
      Array.unsafe_set s (b + 3) (Pattern.eval_at p xform q w))

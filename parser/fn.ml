(* User-defined functions: POV-Ray's function { ... } bodies, compiled
   once into OCaml closures over a slot array (the parameters, then the
   variables of sum()/prod()). Constants fold at compile time. *)

type t = {
  params : string array;
  nslots : int;
  code : float array -> float;
  unsupported : string option;
  vector : (float array -> float array) option;
      (** a vector function (function { transform {...} }) *)
}

let make ~params ~nslots ~unsupported code = { params; nslots; code; unsupported; vector = None }

let of_transform tr =
  let apply (a : float array) =
    let p = Camlray.Transform.point tr (Camlray.Vec3.make a.(0) a.(1) a.(2)) in
    [| p.x; p.y; p.z |]
  in
  { params = [| "x"; "y"; "z" |]; nslots = 3; code = (fun _ -> nan); unsupported = None;
    vector = Some apply }

let of_spline eval =
  { params = [| "t" |]; nslots = 1; code = (fun _ -> nan); unsupported = None;
    vector = Some (fun a -> eval a.(0)) }

let is_vector f = f.vector <> None
let code f = f.code
let nslots f = f.nslots

let slots loc f args =
  (match f.unsupported with Some u -> Diag.error loc "%s" u | None -> ());
  let n = Array.length f.params in
  if List.length args <> n then
    Diag.error loc "this function takes %d argument%s, got %d" n (if n = 1 then "" else "s")
      (List.length args);
  let s = Array.make f.nslots 0. in
  List.iteri (fun i a -> s.(i) <- a) args;
  s

let call loc f args =
  if f.vector <> None then Diag.error loc "this is a vector function: its value is a vector";
  f.code (slots loc f args)

let call_vector loc f args =
  match f.vector with
  | Some v -> v (slots loc f args)
  | None -> Diag.error loc "this is a float function, not a vector function"

let arity f = Array.length f.params
let params f = Array.to_list f.params
let unsupported f = f.unsupported

let eval f args =
  (match f.unsupported with Some u -> invalid_arg u | None -> ());
  if f.vector <> None then invalid_arg "Fn.eval: a vector function";
  if Array.length args <> Array.length f.params then invalid_arg "Fn.eval: wrong number of arguments";
  let s = Array.make f.nslots 0. in
  Array.blit args 0 s 0 (Array.length args);
  f.code s

let eval3 f =
  (match f.unsupported with Some u -> invalid_arg u | None -> ());
  if f.vector <> None then invalid_arg "Fn.eval3: a vector function";
  if Array.length f.params <> 3 then invalid_arg "Fn.eval3: the function does not take 3 arguments";
  let n = f.nslots and code = f.code in
  fun x y z ->
    let s = Array.make n 0. in
    s.(0) <- x; s.(1) <- y; s.(2) <- z;
    code s

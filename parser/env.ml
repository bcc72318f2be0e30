type macro = {
  name : string;
  params : string list;
  body : Toks.t;
  file : string;
  mloc : Loc.t;
}

type binding =
  | Decl of Decl.t
  | Macro of macro
  | Array of binding option array
  | Unsupported of unsupported

and unsupported = {
  feature : string;
  feature_loc : Loc.t;
  declared : Loc.t;
  failure : string option;
}

(* keyed by strings compared as strings (the generic table's polymorphic
   compare showed in profiles of parsing) *)
module H = Hashtbl.Make (String)

type t = { globals : binding H.t; mutable scopes : binding H.t list }

let create () = { globals = H.create 256; scopes = [] }

let find t name =
  let rec go = function
    | [] -> H.find_opt t.globals name
    | s :: rest -> ( match H.find_opt s name with Some b -> Some b | None -> go rest)
  in
  go t.scopes

let declare t name b =
  match List.find_opt (fun s -> H.mem s name) t.scopes with
  | Some s -> H.replace s name b
  | None -> H.replace t.globals name b

let local t name b =
  match t.scopes with
  | s :: _ -> H.replace s name b
  | [] -> H.replace t.globals name b

let undef t name =
  match List.find_opt (fun s -> H.mem s name) t.scopes with
  | Some s -> H.remove s name
  | None -> H.remove t.globals name

let push_scope t = t.scopes <- H.create 16 :: t.scopes
let pop_scope t = match t.scopes with [] -> () | _ :: rest -> t.scopes <- rest

type mark = binding H.t list

let mark t = t.scopes
let restore t m = t.scopes <- m

let names t =
  let acc = ref [] in
  H.iter (fun k _ -> acc := k :: !acc) t.globals;
  List.iter (fun s -> H.iter (fun k _ -> acc := k :: !acc) s) t.scopes;
  List.sort_uniq compare !acc

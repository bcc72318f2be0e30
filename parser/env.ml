type macro = {
  name : string;
  params : string list;
  body : Lexer.token array;
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

type t = { globals : (string, binding) Hashtbl.t; mutable scopes : (string, binding) Hashtbl.t list }

let create () = { globals = Hashtbl.create 256; scopes = [] }

let find t name =
  let rec go = function
    | [] -> Hashtbl.find_opt t.globals name
    | s :: rest -> ( match Hashtbl.find_opt s name with Some b -> Some b | None -> go rest)
  in
  go t.scopes

let declare t name b =
  match List.find_opt (fun s -> Hashtbl.mem s name) t.scopes with
  | Some s -> Hashtbl.replace s name b
  | None -> Hashtbl.replace t.globals name b

let local t name b =
  match t.scopes with
  | s :: _ -> Hashtbl.replace s name b
  | [] -> Hashtbl.replace t.globals name b

let undef t name =
  match List.find_opt (fun s -> Hashtbl.mem s name) t.scopes with
  | Some s -> Hashtbl.remove s name
  | None -> Hashtbl.remove t.globals name

let push_scope t = t.scopes <- Hashtbl.create 16 :: t.scopes
let pop_scope t = match t.scopes with [] -> () | _ :: rest -> t.scopes <- rest

type mark = (string, binding) Hashtbl.t list

let mark t = t.scopes
let restore t m = t.scopes <- m

let names t =
  let acc = ref [] in
  Hashtbl.iter (fun k _ -> acc := k :: !acc) t.globals;
  List.iter (fun s -> Hashtbl.iter (fun k _ -> acc := k :: !acc) s) t.scopes;
  List.sort_uniq compare !acc

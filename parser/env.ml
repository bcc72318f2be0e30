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

(* A name's binding is a cell, rewritten in place when the name is
   declared again: a reader that has found the cell can keep it for as
   long as [gen] has not moved (no name added or removed anywhere, no
   scope entered or left), and read the name again without a lookup. *)
type cell = { mutable b : binding }

type t = { globals : cell H.t; mutable scopes : cell H.t list; mutable gen : int }

let create () = { globals = H.create 256; scopes = []; gen = 0 }
let generation t = t.gen
let binding c = c.b
let moved t = t.gen <- t.gen + 1

let lookup t name =
  let rec go = function
    | [] -> H.find_opt t.globals name
    | s :: rest -> ( match H.find_opt s name with Some c -> Some c | None -> go rest)
  in
  go t.scopes

let find t name = match lookup t name with Some c -> Some c.b | None -> None

let set t table name b =
  match H.find_opt table name with
  | Some c -> c.b <- b
  | None ->
      H.replace table name { b };
      moved t

let declare t name b =
  match List.find_opt (fun s -> H.mem s name) t.scopes with
  | Some s -> set t s name b
  | None -> set t t.globals name b

let local t name b =
  match t.scopes with
  | s :: _ -> set t s name b
  | [] -> set t t.globals name b

let undef t name =
  (match List.find_opt (fun s -> H.mem s name) t.scopes with
  | Some s -> H.remove s name
  | None -> H.remove t.globals name);
  moved t

let push_scope t =
  t.scopes <- H.create 16 :: t.scopes;
  moved t

let pop_scope t =
  (match t.scopes with [] -> () | _ :: rest -> t.scopes <- rest);
  moved t

type mark = cell H.t list

let mark t = t.scopes

let restore t m =
  t.scopes <- m;
  moved t

let local_at t (m : mark) name b = match m with s :: _ -> set t s name b | [] -> set t t.globals name b

let declare_at t (m : mark) name b =
  match List.find_opt (fun s -> H.mem s name) m with
  | Some s -> set t s name b
  | None -> set t t.globals name b

let names t =
  let acc = ref [] in
  H.iter (fun k _ -> acc := k :: !acc) t.globals;
  List.iter (fun s -> H.iter (fun k _ -> acc := k :: !acc) s) t.scopes;
  List.sort_uniq compare !acc

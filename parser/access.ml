type t = All | Only of string list

(* The real path; for a file that does not exist yet (to be written),
   that of its folder. *)
let real p =
  try Unix.realpath p
  with Unix.Unix_error _ -> (
    try Filename.concat (Unix.realpath (Filename.dirname p)) (Filename.basename p)
    with Unix.Unix_error _ -> p)

let create dirs = Only (List.sort_uniq compare (List.map real dirs))
let unrestricted = All
let folders = function All -> [] | Only l -> l

let inside dir path =
  let d = if String.ends_with ~suffix:"/" dir then dir else dir ^ "/" in
  path = dir || (String.length path > String.length d && String.sub path 0 (String.length d) = d)

let check t path =
  match t with
  | All -> Ok ()
  | Only dirs ->
      let p = real path in
      if List.exists (fun d -> inside d p) dirs then Ok ()
      else
        Error
          (Printf.sprintf
             "reading %s is not allowed: scenes may read only inside %s (grant more with --allow-read DIR)"
             path (String.concat ", " dirs))

let limit = ref max_int
let read = ref 0
let placed = ref 0

let reset n =
  limit := n;
  read := 0;
  placed := 0

let too_many loc =
  Diag.error loc "the scene generates more than %d objects (the limit; raise it with --max-objects)"
    !limit

let parsed loc =
  incr read;
  if !read > !limit then too_many loc

(* Nodes of an object tree, counting stops once past [limit] (declared
   objects are shared, so a tree can stand for exponentially many). *)
let rec nodes acc (o : Sdl.obj) =
  if acc > !limit then acc
  else
    let acc = acc + 1 in
    match o.shape with
    | Sdl.Csg (_, cs) | Light_group (_, cs) -> List.fold_left nodes acc cs
    | Inverse c -> nodes acc c
    | Clipped (c, cs) | Bounded (c, cs) -> List.fold_left nodes (nodes acc c) cs
    | Light { looks_like; projected_through; _ } ->
        let acc = match looks_like with Some c -> nodes acc c | None -> acc in
        (match projected_through with Some c -> nodes acc c | None -> acc)
    | _ -> acc

let place (o : Sdl.obj) =
  placed := nodes !placed o;
  if !placed > !limit then too_many o.loc

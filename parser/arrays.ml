(* Arrays: declaration with sizes and initialisers, indexing, copying,
   and the queries defined(), dimensions(), dimension_size(). *)
open Lexer
open Cursor

(* defined(NAME), defined(NAME[i]...), dimensions(ARRAY),
   dimension_size(ARRAY, DIM) *)
let rec query t what loc =
  expect_tok t Parser.LPAREN (Printf.sprintf "'(' after %s" what);
  let name, nloc = expect_ident t "an identifier" in
  let rec element b =
    match (b, (raw_peek t).raw) with
    | Some (Env.Array a), Tok Parser.LBRACKET ->
        ignore (raw_next t);
        let i = Value.to_int nloc (Quick.expr_then_rbracket t) in
        if i < 0 || i >= Array.length a then
          fail t nloc "index %d is outside the array %s (size %d)" i name (Array.length a);
        element a.(i)
    | _, Tok Parser.LBRACKET -> fail t nloc "%s is not an array" name
    | _ -> b
  in
  let b = match Env.find t.env name with
    | Some b -> Some b
    | None ->
        if Cursor.builtin t name <> None || Hashtbl.mem t.handles name then
          Some (Env.Decl (Decl.Value (Value.Float 0.)))
        else None
  in
  let result =
    match what with
    | "defined" -> if element b = None then 0. else 1.
    | _ -> (
        let a = match b with
          | Some (Env.Array a) -> a
          | _ -> fail t nloc "%s: %s is not an array" what name
        in
        let rec dims a =
          Array.length a :: (match if Array.length a > 0 then a.(0) else None with
            | Some (Env.Array a') -> dims a' | _ -> [])
        in
        let ds = dims a in
        if what = "dimensions" then float_of_int (List.length ds)
        else begin
          expect_tok t Parser.COMMA "','";
          let d = Value.to_int loc (Quick.expr_then_rparen t) in
          (* POV-Ray: 0 outside 1 .. dimensions *)
          float_of_int (if d < 1 || d > List.length ds then 0 else List.nth ds (d - 1))
        end)
  in
  if what <> "dimension_size" then expect_tok t Parser.RPAREN "')'";
  result

(* NAME[i][j]...: the element an index chain selects (the array itself
   must be indexed). *)
and element t name a loc : Decl.t =
  let tok = raw_peek t in
  match tok.raw with
  | Tok Parser.LBRACKET ->
      ignore (raw_next t);
      let i = Value.to_int loc (Quick.expr_then_rbracket t) in
      if i < 0 || i >= Array.length a then
        fail t loc "index %d is outside the array %s (size %d)" i name (Array.length a);
      (match a.(i) with
      | None -> fail t loc "element %s[%d] has not been set" name i
      | Some (Env.Decl d) -> d
      | Some (Env.Array a') -> element t (Printf.sprintf "%s[%d]" name i) a' loc
      | Some (Env.Macro _) -> fail t loc "an array cannot hold a macro"
      | Some (Env.Unsupported u) -> unsupported_name t (Printf.sprintf "%s[%d]" name i) u loc)
  | _ -> fail t loc "the array %s must be indexed: %s[...]" name name

and copy a =
  Array.map (function Some (Env.Array a') -> Some (Env.Array (copy a')) | x -> x) a

and make t loc =
  let rec dims acc =
    match (raw_peek t).raw with
    | Tok Parser.LBRACKET ->
        ignore (raw_next t);
        let n = Value.to_int loc (Quick.expr_then_rbracket t) in
        if n <= 0 then fail t loc "array size must be positive, found %d" n;
        dims (n :: acc)
    | _ -> List.rev acc
  in
  let ds = dims [] in
  if ds = [] then fail t loc "expected [size] after array";
  let total = List.fold_left ( * ) 1 ds in
  if total > t.config.limits.max_array_size then
    fail t loc "array of %d elements exceeds the limit %d (raise it with --max-array)" total
      t.config.limits.max_array_size;
  let rec make = function
    | [] -> assert false
    | [ n ] -> Array.make n None
    | n :: rest -> Array.init n (fun _ -> Some (Env.Array (make rest)))
  in
  let a = make ds in
  (match (raw_peek t).raw with
  | Tok Parser.LBRACE -> fill t loc a ds
  | _ -> ());
  a

and fill t loc a ds =
  ignore (raw_next t);
  (* at '{' already consumed *)
  match ds with
  | [ n ] ->
      let rec go i =
        if i >= n then
          (* a trailing comma before '}' is allowed *)
          match (raw_peek t).raw with
          | Tok Parser.RBRACE -> ignore (raw_next t)
          | _ -> fail t loc "too many initialisers (the array has %d elements)" n
        else begin
          (* commas between elements are optional *)
          t.optional_sep <- Some Parser.COMMA;
          let d, closed = Cursor.parse t Parser.Incremental.array_elem in
          a.(i) <- Some (Env.Decl d);
          if not closed then go (i + 1)
          else if i + 1 <> n then fail t loc "%d initialisers for an array of %d" (i + 1) n
        end
      in
      go 0
  | n :: rest ->
      for i = 0 to n - 1 do
        (match a.(i) with
        | Some (Env.Array sub) ->
            (match (raw_peek t).raw with
            | Tok Parser.LBRACE -> fill t loc sub rest
            | r -> fail t loc "expected '{' for a row of the array, found %s" (describe r))
        | _ -> assert false);
        let sep = raw_next t in
        match sep.raw with
        | Tok Parser.COMMA when i < n - 1 -> ()
        | Tok Parser.RBRACE when i = n - 1 -> ()
        | r -> fail t sep.loc "expected %s, found %s" (if i < n - 1 then "','" else "'}'") (describe r)
      done
  | [] -> assert false


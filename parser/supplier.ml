module I = Parser.MenhirInterpreter
open Lexer
open Cursor

type limits = Cursor.limits = {
  max_loop_iterations : int;
  max_macro_depth : int;
  max_include_depth : int;
  max_array_size : int;
  max_tokens : int;  (** raw tokens read in all, loops and macros included *)
  max_objects : int;  (** objects read or placed, see {!Budget} *)
}

let default_limits = Cursor.default_limits

type config = Cursor.config = {
  include_dirs : string list;
  limits : limits;
  builtins : (string * float) list;
  access : Access.t;
  fold : bool;
  quick : bool;
}

type t = Cursor.t

let files_read = Cursor.files_read
let close_files = Dataio.close_files

(* ---------- typing identifiers ---------- *)

let token_of_decl : Decl.t -> Parser.token = function
  | Decl.Value (Value.Float f) -> Parser.FLOAT_ID f
  | Decl.Value (Value.Vector a) -> Parser.VECTOR_ID a
  | Decl.Value (Value.String s) -> Parser.STRING_ID s
  | Decl.Object o -> Parser.OBJECT_ID o
  | Decl.Pigment p -> Parser.PIGMENT_ID p
  | Decl.Finish f -> Parser.FINISH_ID f
  | Decl.Texture x -> Parser.TEXTURE_ID x
  | Decl.Interior i -> Parser.INTERIOR_ID i
  | Decl.Transform x -> Parser.TRANSFORM_ID x
  | Decl.Camera c -> Parser.CAMERA_ID c
  | Decl.Function f -> Parser.FUNCTION_ID f
  | Decl.Spline _ -> Parser.UNDEFINED_ID "a spline (call it: S(t))"
  | Decl.Color_map m -> Parser.COLOR_MAP_ID m
  | Decl.Normal n -> Parser.NORMAL_ID n
  | Decl.Material m -> Parser.MATERIAL_ID m
  | Decl.Sky_sphere k -> Parser.SKY_SPHERE_ID k
  | Decl.Media m -> Parser.MEDIA_ID m
  | Decl.Density d -> Parser.DENSITY_ID d

let suggest t name =
  let d a b =
    (* Levenshtein distance, small strings *)
    let la = String.length a and lb = String.length b in
    let m = Array.make_matrix (la + 1) (lb + 1) 0 in
    for i = 0 to la do m.(i).(0) <- i done;
    for j = 0 to lb do m.(0).(j) <- j done;
    for i = 1 to la do
      for j = 1 to lb do
        let c = if a.[i - 1] = b.[j - 1] then 0 else 1 in
        m.(i).(j) <- min (min (m.(i - 1).(j) + 1) (m.(i).(j - 1) + 1)) (m.(i - 1).(j - 1) + c)
      done
    done;
    m.(la).(lb)
  in
  let best =
    List.fold_left
      (fun acc n ->
        let k = d (String.lowercase_ascii name) (String.lowercase_ascii n) in
        match acc with
        | Some (_, k') when k' <= k -> acc
        | _ -> if k <= max 1 (String.length name / 3) then Some (n, k) else acc)
      None (Env.names t.env)
  in
  match best with Some (n, _) -> Printf.sprintf " (did you mean %s?)" n | None -> ""

(* ---------- the sub-parse driver ---------- *)

(* the words only an isosurface reads *)
let iso_word = function
  | Parser.ACCURACY -> Some "accuracy"
  | Parser.MAX_GRADIENT -> Some "max_gradient"
  | Parser.EVALUATE -> Some "evaluate"
  | Parser.MAX_TRACE -> Some "max_trace"
  | Parser.ALL_INTERSECTIONS -> Some "all_intersections"
  | Parser.CONTAINED_BY -> Some "contained_by"
  | _ -> None

let acceptable_probe : Parser.token list =
  Parser.[ LBRACE; RBRACE; LPAREN; RPAREN; LT; GT; COMMA; SEMI; FLOAT 0.; STRING "";
           UNDEFINED_ID ""; EQ ]

let rec next t : Parser.token * Loc.t =
  match t.pending with
  | x :: rest ->
      t.pending <- rest;
      x
  | [] when (match t.stop_at with Some (f, p) -> top t == f && f.pos = p | None -> false) ->
      t.stop_at <- None;
      let l = (Toks.get (top t).toks (top t).pos).loc in
      (Parser.SEMI, { l with stop = l.start })
  | [] -> (
      let tok = raw_next t in
      match tok.raw with
      | Eof -> (Parser.EOF, tok.loc)
      | Tok x ->
          (match x with
          | Parser.LBRACE -> t.braces <- tok.loc :: t.braces
          | Parser.RBRACE -> (match t.braces with _ :: r -> t.braces <- r | [] -> ())
          | _ -> ());
          (x, tok.loc)
      | Directive d ->
          directive t d tok.loc;
          next t
      | Ident name -> ident t name tok.loc)

and ident t name loc =
  match Cursor.builtin t name with
  | Some v -> (Parser.FLOAT v, loc)
  | None when name = "version" -> (Parser.FLOAT (Defaults.version ()), loc)
  | None -> (
      (match if Hashtbl.length t.deprecated = 0 then None else Hashtbl.find_opt t.deprecated name with
      | Some (msg, once, warned) when not (once && !warned) ->
          warned := true;
          Diag.warning loc (Printf.sprintf "%s is deprecated: %s" name msg)
      | _ -> ());
      match Env.find t.env name with
      | Some (Env.Decl (Decl.Spline s)) -> (Parser.VECTOR (Splread.call t s loc), loc)
      | Some (Env.Decl d) -> (token_of_decl d, loc)
      | Some (Env.Macro m) ->
          Macros.call t m loc;
          next t
      | Some (Env.Array a) -> (token_of_decl (Arrays.element t name a loc), loc)
      | Some (Env.Unsupported u) -> unsupported_name t name u loc
      | None ->
          if name = "default" && (raw_peek t).raw = Tok Parser.LBRACE then begin
            (* 'default { ... }' without '#': POV-Ray accepts it too *)
            parse t Parser.Incremental.default_body;
            next t
          end
          else if name = "function" then
            match (raw_peek t).raw with
            | Tok Parser.LPAREN | Tok Parser.LBRACE -> (Parser.FUNCTION_LIT (function_lit t loc), loc)
            | _ ->
                (* height_field's function W, H { ... }: POV-Ray rounds the sizes *)
                let size v = int_of_float (Float.floor (Value.to_float loc v +. 0.5)) in
                let w = size (Quick.expr_then_comma t) in
                let h = size (parse t Parser.Incremental.expr_then_lbrace) in
                let f, text = function_body t loc [ "x"; "y"; "z" ] in
                (Parser.FUNCTION_SIZED (w, h, f, text), loc)
          else if List.mem name [ "trace"; "inside"; "min_extent"; "max_extent" ] then probe t name loc
          else if name = "charset" then begin
            (* global_settings { charset ascii | utf8 | sys }: how text
               objects read their strings *)
            let w = raw_next t in
            (match w.raw with
            | Ident "ascii" -> Defaults.set_charset `Ascii
            | Ident "utf8" -> Defaults.set_charset `Utf8
            | Tok (Parser.IMAGE_KIND "sys") -> Defaults.set_charset `Sys
            | _ -> fail t w.loc "charset takes ascii, utf8 or sys");
            next t
          end
          else if name = "hf_gray_16" then begin
            (* an output setting (16-bit grey files): read and ignored *)
            (match (raw_peek t).raw with
            | Tok (Parser.FLOAT _) | Ident ("on" | "off" | "true" | "false" | "yes" | "no") -> ignore (raw_next t)
            | _ -> ());
            if not (List.mem name t.skipped) then begin
              t.skipped <- name :: t.skipped;
              Diag.warning loc "hf_gray_16 (16-bit grey output files) is read and ignored"
            end;
            next t
          end
          else if name = "file_exists" then begin
            expect_tok t Parser.LPAREN "'(' after file_exists";
            let file = parse t Parser.Incremental.string_arg in
            expect_tok t Parser.RPAREN "')'";
            (Parser.FLOAT (if find_file t file <> None then 1. else 0.), loc)
          end
          else if name = "defined" || name = "dimensions" || name = "dimension_size" then
            (Parser.FLOAT (Arrays.query t name loc), loc)
          else if List.mem name [ "linear_spline"; "quadratic_spline"; "cubic_spline"; "bezier_spline";
                                  "linear_sweep"; "conic_sweep" ] then
            (* a prism's words (a spline { } reads its own kind) *)
            (Parser.SPLINE_KIND name, loc)
          else if name = "array" then fail t loc "arrays can only be created with #declare NAME = array[N]"
          else if Lexer.pov_reserved name then
            (* a POV-Ray word camlray does not know: inside a #declare the
               name becomes a marker (see [guarded]), elsewhere an error *)
            unsupported t loc { feature = name; feature_loc = loc; declared = loc; failure = None }
              "%s is not supported by camlray" name
          else (Parser.UNDEFINED_ID name, loc))

(* trace(O, A, B [, N]), inside(O, P), min_extent(O), max_extent(O): the
   object is named by a declared identifier (as POV-Ray requires); trace's
   N, a vector identifier, receives the normal ([#declare]'s scope). *)
and probe t name loc =
  expect_tok t Parser.LPAREN (Printf.sprintf "'(' after %s" name);
  let n, nloc = expect_ident t (Printf.sprintf "the name of a declared object in %s(...)" name) in
  let o =
    match Env.find t.env n with
    | Some (Env.Decl (Decl.Object o)) -> o
    | Some (Env.Unsupported u) -> ignore (unsupported_name t n u nloc); assert false
    | Some (Env.Decl d) -> fail t nloc "%s needs an object: %s is %s" name n (Decl.kind_name d)
    | _ -> fail t nloc "%s needs a declared object: %s is not one%s" name n (suggest t n)
  in
  let vector (v : Camlray.Vec3.t) = Parser.VECTOR [| v.x; v.y; v.z |] in
  match name with
  | "min_extent" | "max_extent" ->
      expect_tok t Parser.RPAREN "')'";
      (vector (Probe.extent loc o ~max:(name = "max_extent")), loc)
  | "inside" ->
      expect_tok t Parser.COMMA "','";
      let p = Quick.expr_then_rparen t in
      (Parser.FLOAT (if Probe.inside loc o (Value.to_vec3 loc p) then 1. else 0.), loc)
  | _ ->
      expect_tok t Parser.COMMA "','";
      let a = Quick.expr_then_comma t in
      let b, more = Quick.expr_then_sep t in
      let point, normal = Probe.trace loc o (Value.to_vec3 loc a) (Value.to_vec3 loc b) in
      if more then begin
        let v, vloc = expect_ident t "the name of a vector identifier to receive the normal" in
        (match Env.find t.env v with
         | None | Some (Env.Decl (Decl.Value _)) -> ()
         | Some (Env.Decl d) -> fail t vloc "trace's normal goes into a vector identifier: %s is %s" v (Decl.kind_name d)
         | Some _ -> fail t vloc "trace's normal goes into a vector identifier: %s is not one" v);
        expect_tok t Parser.RPAREN "')'";
        Env.declare t.env v (Env.Decl (Decl.Value (Value.Vector [| normal.x; normal.y; normal.z |])))
      end;
      (vector point, loc)

(* function [(params)] { body }: the body is read here, token by token,
   and compiled by Fnparse; directives may not stand inside it. *)
and function_lit t loc =
  let params =
    match (raw_peek t).raw with
    | Tok Parser.LPAREN ->
        ignore (raw_next t);
        let rec go acc =
          let tok = raw_next t in
          match Fnparse.word tok.raw with
          | Some p -> (
              if List.mem p acc then fail t tok.loc "parameter %s is listed twice" p;
              let sep = raw_next t in
              match sep.raw with
              | Tok Parser.COMMA -> go (p :: acc)
              | Tok Parser.RPAREN -> List.rev (p :: acc)
              | r -> fail t sep.loc "expected ',' or ')' in the parameter list, found %s" (describe r))
          | None -> (
              match tok.raw with
              | Tok Parser.RPAREN when acc = [] -> []
              | r -> fail t tok.loc "expected a parameter name, found %s" (describe r))
        in
        go []
    | _ -> [ "x"; "y"; "z" ]
  in
  expect_tok t Parser.LBRACE "'{' to open the function's body";
  fst (function_body t loc params)

(* the body after its '{', and its text when it is an expression *)
and function_body t loc params =
  match (raw_peek t).raw with
  | Tok Parser.TRANSFORM ->
      if params <> [ "x"; "y"; "z" ] then fail t loc "a transform function takes no parameter list";
      let tr = parse t Parser.Incremental.transform_arg in
      expect_tok t Parser.RBRACE "'}' to close the function";
      (Fn.of_transform tr, None)
  | Ident "spline" ->
      if params <> [ "x"; "y"; "z" ] then fail t loc "a spline function takes no parameter list";
      let sloc = (raw_next t).loc in
      let s = Splread.read t sloc in
      expect_tok t Parser.RBRACE "'}' to close the function";
      (Fn.of_spline s, None)
  | Tok Parser.PIGMENT -> (
      if params <> [ "x"; "y"; "z" ] then fail t loc "a pigment function takes no parameter list";
      match parse t Parser.Incremental.declare_rhs with
      | Decl.Pigment p ->
          expect_tok t Parser.RBRACE "'}' to close the function";
          (Fn.of_pigment p, None)
      | _ -> fail t loc "expected a pigment { ... } in this function")
  | Ident "pattern" when params = [ "x"; "y"; "z" ] -> (
      (* function { pattern { P } }: P's value, read as a pigment's
         pattern is (its transformations, waves and warps) *)
      let ploc = (raw_next t).loc in
      t.pending <- [ (Parser.PIGMENT, ploc) ];
      match parse t Parser.Incremental.declare_rhs with
      | Decl.Pigment (Camlray.Pigment.Map { pattern; xform; _ } | Camlray.Pigment.Blocks { pattern; xform; _ }) ->
          expect_tok t Parser.RBRACE "'}' to close the function";
          (Fn.of_pattern pattern xform, None)
      | _ -> fail t ploc "expected a pattern in pattern { ... }: gradient x, checker, bozo, ...")
  | _ ->
  let rec body depth acc =
    let tok = raw_next t in
    match tok.raw with
    | Eof -> fail t loc "this function's body has no closing '}'"
    | Directive d -> fail t tok.loc "#%s cannot stand inside a function's body" d
    | Tok Parser.LBRACE -> body (depth + 1) (tok :: acc)
    | Tok Parser.RBRACE ->
        if depth = 0 then List.rev ({ raw = Eof; loc = tok.loc } :: acc)
        else body (depth - 1) (tok :: acc)
    | _ -> body depth (tok :: acc)
  in
  let toks = Array.of_list (body 0 []) in
  if Array.length toks = 1 then fail t loc "a function's body cannot be empty";
  let resolve nloc name =
    match Cursor.builtin t name with
    | Some v -> Fnparse.Const v
    | None -> (
        match Env.find t.env name with
        | Some (Env.Decl (Decl.Value (Value.Float f))) -> Fnparse.Const f
        | Some (Env.Decl (Decl.Value (Value.Vector a))) -> Fnparse.Vec a
        | Some (Env.Decl (Decl.Function f)) -> Fnparse.Func f
        | Some (Env.Unsupported u) -> unsupported_name t name u nloc
        | _ -> Fnparse.Unknown)
  in
  (Fnparse.compile ~resolve ~params toks, source_text toks)

(* the text of a function's body from its tokens (None if one of them
   cannot be written back) *)
and source_text toks =
  let word = function
    | Ident s -> Some s
    | Eof -> Some ""
    | Directive _ -> None
    | Tok tk -> (
        match tk with
        | Parser.FLOAT f -> Some (Printf.sprintf "%.17g" f)
        | Parser.FUNC f -> Some f
        | Parser.MEMBER m -> Some ("." ^ m)
        | Parser.STRING s -> Some (Printf.sprintf "%S" s)
        | Parser.LBRACE -> Some "{" | Parser.RBRACE -> Some "}" | Parser.LPAREN -> Some "("
        | Parser.RPAREN -> Some ")" | Parser.LBRACKET -> Some "[" | Parser.RBRACKET -> Some "]"
        | Parser.LT -> Some "<" | Parser.GT -> Some ">" | Parser.LE -> Some "<=" | Parser.GE -> Some ">="
        | Parser.EQ -> Some "=" | Parser.NE -> Some "!=" | Parser.PLUS -> Some "+" | Parser.MINUS -> Some "-"
        | Parser.STAR -> Some "*" | Parser.SLASH -> Some "/" | Parser.COMMA -> Some ","
        | Parser.QUESTION -> Some "?" | Parser.COLON -> Some ":" | Parser.AND -> Some "&" | Parser.OR -> Some "|"
        | Parser.BANG -> Some "!"
        | Parser.RGB k | Parser.CHANNEL k -> Some k
        | _ -> Lexer.keyword_of (Tok tk))
  in
  let rec go acc i =
    if i >= Array.length toks then Some (String.concat " " (List.rev acc))
    else match word toks.(i).raw with
      | Some "" -> go acc (i + 1)
      | Some w -> go (w :: acc) (i + 1)
      | None -> None
  in
  go [] 0

and parse : 'a. t -> (Lexing.position -> 'a I.checkpoint) -> 'a =
 fun t start ->
  let pos = (Toks.get (top t).toks (top t).pos).loc.start in
  let sep = t.optional_sep and probe = t.semi_probe in
  t.optional_sep <- None;
  t.semi_probe <- None;
  let frame = top t in
  (* [prev]: the checkpoint the last token was offered to; [orig]: the
     tokens of the folded run [last] stands for, if it is one *)
  let rec loop cp prev last orig shifted =
    match cp with
    | I.InputNeeded _ -> (
        let read () =
          if t.depth = 1 then release_behind t;
          let from_raw = t.pending = [] in
          let ((tok, first) as x) = next t in
          (* an isosurface's words elsewhere (a normal's accuracy): POV-Ray
             words camlray does not know there *)
          (match iso_word tok with
           | Some name when not (I.acceptable cp tok first.start) ->
               unsupported t first { feature = name; feature_loc = first; declared = first; failure = None }
                 "%s is not supported by camlray" name
           | _ -> ());
          (* a run is read only where the parser takes its first token:
             nothing is read past where the parser would stop *)
          let (tok, loc), orig =
            if from_raw && t.config.fold && Fold.may_start t last tok then
              let accepts v = I.acceptable cp v first.start in
              (* a run read before is replayed where the parser takes the
                 vector it makes (which it can only where it takes the
                 '<' too): the '<' itself need not be tried *)
              match Fold.replay t ~accepts x with
              | Some y -> (y, [])
              | None -> if accepts tok then Fold.run t ~next ~accepts x else (x, [])
            else (x, [])
          in
          t.last <- loc;
          loop (I.offer cp (tok, loc.start, loc.stop)) cp (Some (tok, loc)) orig false
        in
        let ends what (loc : Loc.t) r =
          if I.acceptable cp Parser.SEMI loc.start then begin
            r := Some (what, loc);
            loop (I.offer cp (Parser.SEMI, loc.start, loc.start)) cp None [] true
          end
          else read ()
        in
        match probe with
        | Some r when t.pending = [] && top t == frame -> (
            match raw_peek t with
            | { raw = Directive d; loc }
              when not (List.mem d [ "else"; "elseif"; "end"; "case"; "range"; "break" ]) ->
                ends ("#" ^ d) loc r
            | { raw = Eof; loc } -> ends "end of file" loc r
            | _ -> read ())
        | _ -> read ())
    | I.Shifting _ -> loop (I.resume cp) prev last orig true
    | I.AboutToReduce _ -> loop (I.resume cp) prev last orig shifted
    | I.HandlingError env -> (
        match (sep, last, orig) with
        | Some s, Some ((tok, loc) as x), _ when tok <> s && I.acceptable prev s loc.start ->
            (* the optional separator was left out: supply it, and give
               the token again after it *)
            (match tok with
            | Parser.LBRACE -> (match t.braces with _ :: r -> t.braces <- r | [] -> ())
            | Parser.RBRACE -> t.braces <- loc :: t.braces
            | _ -> ());
            t.pending <- x :: t.pending;
            loop (I.offer prev (s, loc.start, loc.start)) prev None [] true
        | _, _, ((tok, loc) as x) :: rest ->
            (* a folded run the parser does not take: give it the run's
               own tokens, so that it fails (or goes on) as it would have *)
            t.pending <- rest @ t.pending;
            t.last <- loc;
            loop (I.offer prev (tok, loc.start, loc.stop)) prev (Some x) [] false
        | _ -> syntax_error t env last)
    | I.Accepted v ->
        (match last with
        | Some x when not shifted -> t.pending <- x :: t.pending
        | _ -> ());
        v
    | I.Rejected -> fail t t.last "syntax error"
  in
  let cp0 = start pos in
  t.depth <- t.depth + 1;
  match loop cp0 cp0 None [] true with
  | v -> t.depth <- t.depth - 1; v
  | exception e -> t.depth <- t.depth - 1; raise e

(* Between two tokens of the scene's own parse no directive is half
   read: what the top frame has passed is not read again unless a loop
   is open in it (it jumps back) or a declaration waits for a position. *)
and release_behind t =
  let f = top t in
  match f.kind with
  | Macro_call _ -> ()
  | Main | Include _ -> if f.ctrl = [] && t.stop_at = None then Toks.release f.toks f.pos

and syntax_error : 'a. t -> 'a I.env -> (Parser.token * Loc.t) option -> 'b =
 fun t env last ->
  let tok, loc = match last with Some x -> x | None -> (Parser.EOF, t.last) in
  match tok with
  | Parser.UNDEFINED_ID name -> fail t loc "undefined identifier %s%s" name (suggest t name)
  | _ ->
      let found = describe (Tok tok) in
      let expected =
        List.filter_map
          (fun probe ->
            let cp = I.input_needed env in
            if I.acceptable cp probe loc.start then
              Some
                (match probe with
                | Parser.FLOAT _ -> "a number"
                | Parser.STRING _ -> "a string"
                | Parser.UNDEFINED_ID _ -> "an identifier"
                | _ -> describe (Tok probe))
            else None)
          acceptable_probe
      in
      let semi = List.mem "';'" expected in
      let msg =
        match Messages.message (I.current_state_number env) with
        | m -> Printf.sprintf "%s, found %s" (String.trim m) found
        | exception Not_found -> (
            match expected with
            | [] -> "unexpected " ^ found
            | _ when semi -> Printf.sprintf "expected an operator or ';', found %s" found
            | l -> Printf.sprintf "expected %s, found %s" (String.concat " or " l) found)
      in
      let hint =
        match (t.context, tok, t.braces) with
        | Some c, _, _ when semi -> Printf.sprintf " (%s ends with ';')" c
        | _, Parser.EOF, b :: _ ->
            Printf.sprintf " (the '{' at line %d, column %d is not closed)" (Loc.line b) (Loc.col b)
        | _ -> ""
      in
      fail t loc "%s%s" msg hint

(* ---------- directives ---------- *)

and directive t d loc =
  let f = top t in
  match d with
  | "version" ->
      let v = Value.to_float loc (parse t Parser.Incremental.expr_then_semi) in
      Defaults.set_version v
  | "declare" | "local" -> declare t ~local:(d = "local") loc
  | "undef" ->
      let name, _ = expect_ident t "an identifier after #undef" in
      Env.undef t.env name
  | "include" -> Macros.include_file t loc
  | "if" ->
      let c = Value.to_bool loc (Quick.paren_expr t) in
      Control.enter_if t loc c
  | "ifdef" | "ifndef" ->
      let defined = Arrays.query t "defined" loc = 1. in
      Control.enter_if t loc (if d = "ifdef" then defined else not defined)
  | "elseif" | "else" -> (
      match f.ctrl with
      | In_if _ :: rest ->
          (* the taken branch ends here: skip to #end *)
          f.ctrl <- rest;
          Control.skip_to_end t
      | In_switch _ :: _ when d = "else" -> () (* falling through into #else *)
      | _ -> fail t loc "#%s without a matching #if" d)
  | "end" -> Control.end_block t loc
  | "while" ->
      let cond_pos = f.pos in
      let c = Value.to_bool loc (Quick.paren_expr t) in
      if c then f.ctrl <- In_while { cond_pos; count = 1; wloc = loc } :: f.ctrl else Control.skip_to_end t
  | "for" -> Control.for_loop t loc
  | "switch" -> Control.switch t loc
  | "case" | "range" -> (
      match f.ctrl with
      | In_switch _ :: _ ->
          (* fall through: skip this clause's condition *)
          Control.skip_condition t
      | _ -> fail t loc "#%s outside #switch" d)
  | "break" -> Control.break t loc
  | "macro" -> Macros.define t loc
  | "debug" | "warning" | "error" ->
      let s = parse t Parser.Incremental.string_arg in
      if d = "debug" then (prerr_string s; flush stderr)
      else if d = "warning" then Diag.warning loc s
      else fail t loc "#error: %s" s
  | "default" -> parse t Parser.Incremental.default_body
  | "fopen" -> Dataio.fopen t loc
  | "fclose" -> Dataio.fclose t
  | "write" -> Dataio.write t loc
  | "read" -> Dataio.read t loc
  | _ -> fail t loc "unknown directive #%s" d

and declare t ~local loc =
  let name, nloc = expect_ident t "an identifier after #declare" in
  let name, nloc =
    if name <> "deprecated" then (name, nloc)
    else begin
      (* #declare deprecated [once] "message" NAME = ... *)
      let once =
        match (raw_peek t).raw with Ident "once" | Tok Parser.ONCE -> ignore (raw_next t); true | _ -> false
      in
      let msg =
        match (raw_next t).raw with
        | Tok (Parser.STRING m) -> m
        | r -> fail t nloc "expected the deprecation message (a string), found %s" (describe r)
      in
      let name, nloc = expect_ident t "the identifier being declared" in
      Hashtbl.replace t.deprecated name (msg, once, ref false);
      (name, nloc)
    end
  in
  if Lexer.pov_reserved name then fail t nloc "%s is a reserved word and cannot be declared" name;
  (* the scope the directive stands in: the value may end inside a
     macro's body (#local V = M() where M's body ends with 'Q;') *)
  let scope = Env.mark t.env in
  let bind b = if local then Env.local_at t.env scope name b else Env.declare_at t.env scope name b in
  match (raw_peek t).raw with
  | Tok Parser.LBRACKET -> (
      (* element assignment: NAME[i]... = value *)
      let rec target a =
        ignore (raw_next t);
        let i = Value.to_int loc (Quick.expr_then_rbracket t) in
        if i < 0 || i >= Array.length a then
          fail t nloc "index %d is outside the array %s (size %d)" i name (Array.length a);
        match (raw_peek t).raw with
        | Tok Parser.LBRACKET -> (
            match a.(i) with
            | Some (Env.Array a') -> target a'
            | _ -> fail t nloc "%s has fewer dimensions than indices" name)
        | _ -> (a, i)
      in
      match Env.find t.env name with
      | Some (Env.Array a) ->
          let a, i = target a in
          expect_tok t Parser.EQ "'='";
          a.(i) <- Some (guarded t nloc (fun () -> Env.Decl (rhs t)))
      | _ -> fail t nloc "%s is not an array" name)
  | _ -> (
      expect_tok t Parser.EQ "'=' after the identifier";
      match (raw_peek t).raw with
      | Ident "spline" ->
          let sloc = (raw_next t).loc in
          bind (guarded t nloc (fun () -> Env.Decl (Decl.Spline (Splread.read t sloc))));
          (match (raw_peek t).raw with Tok Parser.SEMI -> ignore (raw_next t) | _ -> ())
      | Ident "array" ->
          ignore (raw_next t);
          bind (guarded t nloc (fun () -> Env.Array (Arrays.make t loc)));
          (match (raw_peek t).raw with Tok Parser.SEMI -> ignore (raw_next t) | _ -> ())
      | _ -> (
          (* #declare A = M(...) where the macro's body ends with a whole
             array (POV-Ray's benchmark.pov): the call is made and the
             body's directives run, as the parser's supplier would, up to
             the body's first token, which the check below then sees. Only
             for a body whose last token names an array it makes
             (#local X = array ... X): a value the parser reads must be
             read from the caller's frame *)
          let returns_array (m : Env.macro) =
            let b = m.body in
            let rec last i = if Toks.mem b (i + 1) && (Toks.get b (i + 1)).raw <> Eof then last (i + 1) else i in
            let k = last 0 in
            match (Toks.get b k).raw with
            | Ident x ->
                let rec makes i =
                  i + 3 <= k
                  && ((match ((Toks.get b i).raw, (Toks.get b (i + 1)).raw, (Toks.get b (i + 2)).raw, (Toks.get b (i + 3)).raw) with
                      | Directive ("local" | "declare"), Ident y, Tok Parser.EQ, Ident "array" -> y = x
                      | _ -> false)
                     || makes (i + 1))
                in
                k > 0 && (match (Toks.get b (k - 1)).raw with Tok Parser.SEMI | Directive _ | Ident _ -> true | _ -> false) && makes 0
            | _ -> false
          in
          let rec enter_calls () =
            let f = top t in
            if t.pending = [] && Toks.mem f.toks (f.pos + 1) then
              match ((Toks.get f.toks f.pos).raw, (Toks.get f.toks (f.pos + 1)).raw) with
              | Ident n, Tok Parser.LPAREN -> (
                  match Env.find t.env n with
                  | Some (Env.Macro m) when returns_array m ->
                      let tok = raw_next t in
                      Macros.call t m tok.loc;
                      skip_directives ()
                  | _ -> ())
              | _ -> ()
          and skip_directives () =
            match (raw_peek t).raw with
            | Directive d ->
                let tok = raw_next t in
                directive t d tok.loc;
                skip_directives ()
            | _ -> enter_calls ()
          in
          enter_calls ();
          (* #declare A = B; for B a whole array or a function (not a call) *)
          let f = top t in
          let whole =
            match (Toks.get f.toks f.pos).raw with
            | Ident n when t.pending = [] && Toks.mem f.toks (f.pos + 1) -> (
                match (Env.find t.env n, (Toks.get f.toks (f.pos + 1)).raw) with
                | Some (Env.Array a), r when r <> Tok Parser.LBRACKET -> Some (Env.Array (Arrays.copy a))
                | Some (Env.Decl (Decl.Function _) as b), r when r <> Tok Parser.LPAREN -> Some b
                | _ -> None)
            | _ -> None
          in
          match whole with
          | Some b ->
              f.pos <- f.pos + 1;
              bind b;
              (match (raw_peek t).raw with Tok Parser.SEMI -> ignore (raw_next t) | _ -> ())
          | None -> bind (guarded t nloc (fun () -> Env.Decl (rhs t)))))

(* Evaluate a right-hand side; if it meets something camlray does not
   support, go back to where it started, skip it (balanced brackets, up
   to a ';' or a closing '}') and bind a marker instead: the error is
   reported where the name is used. In an include file (often one of
   POV-Ray's own), any error in a #declare is deferred the same way. *)
and guarded t nloc f =
  let frames = t.frames in
  let saved = List.map (fun fr -> (fr.pos, fr.ctrl)) frames in
  let pending = t.pending and scopes = Env.mark t.env and braces = t.braces in
  let context = t.context and stop_at = t.stop_at and version = Defaults.version () in
  let recover () =
    t.frames <- frames;
    List.iter2 (fun fr (pos, ctrl) -> fr.pos <- pos; fr.ctrl <- ctrl) frames saved;
    t.pending <- pending;
    t.braces <- braces;
    t.context <- context;
    t.stop_at <- stop_at;
    Defaults.restore_version version;
    Env.restore t.env scopes;
    skip_phrase t
  in
  let in_include = match frames with { kind = Include _; _ } :: _ -> true | _ -> false in
  try f () with
  | Unsupported_use (_, u) ->
      recover ();
      Env.Unsupported { u with declared = nloc }
  | Diag.Error d when in_include ->
      recover ();
      Env.Unsupported { feature = ""; feature_loc = d.loc; declared = nloc; failure = Some d.msg }

(* A string #declare may end without ';' (POV-Ray's rule). A string
   expression is one term (a literal, a string identifier or a string
   function's call), so whether a ';' follows can be seen in the raw
   tokens; without one, the string is parsed with no lookahead, so that
   a directive right after it runs only once the name is bound. *)
and string_without_semi t =
  let f = top t in
  let at i = if Toks.mem f.toks i then (Toks.get f.toks i).raw else Eof in
  let after_term =
    if t.pending <> [] then None
    else
      match at f.pos with
      | Tok (Parser.STRING _) -> Some (f.pos + 1)
      | Ident n when (match Env.find t.env n with Some (Env.Array _) -> false | _ -> true) -> (
          match Env.find t.env n with
          | Some (Env.Decl (Decl.Value (Value.String _))) -> Some (f.pos + 1)
          | _ -> None)
      | Ident _ ->
          (* an array element, NAME[i]...: the term ends after the brackets *)
          let rec close i depth =
            match at i with
            | Tok Parser.LBRACKET -> close (i + 1) (depth + 1)
            | Tok Parser.RBRACKET ->
                if depth = 1 then (match at (i + 1) with Tok Parser.LBRACKET -> close (i + 1) 0 | _ -> Some (i + 1))
                else close (i + 1) (depth - 1)
            | Eof | Directive _ -> None
            | _ when depth = 0 -> None
            | _ -> close (i + 1) depth
          in
          close (f.pos + 1) 0
      | Tok (Parser.FUNC name) when List.exists (String.equal name) string_functions && at (f.pos + 1) = Tok Parser.LPAREN ->
          let rec close i depth =
            match at i with
            | Tok Parser.LPAREN -> close (i + 1) (depth + 1)
            | Tok Parser.RPAREN -> if depth = 1 then Some (i + 1) else close (i + 1) (depth - 1)
            | Eof | Directive _ -> None
            | _ -> close (i + 1) depth
          in
          close (f.pos + 1) 0
      | _ -> None
  in
  match after_term with
  | Some i -> (
      match at i with
      | Tok (Parser.SEMI | Parser.PLUS | Parser.MINUS | Parser.STAR | Parser.SLASH | Parser.MEMBER _) -> `Plain
      | _ -> ( match at f.pos with Ident n when Env.find t.env n <> None && at (f.pos + 1) = Tok Parser.LBRACKET -> `Bounded (f, i) | _ -> `String))
  | None -> `Plain

(* compared by [String.equal]: [List.mem] compares with the polymorphic
   [compare_val], 2% of a parse of #declares in a loop (mesh-camera.pov) *)
and string_functions = [ "concat"; "str"; "chr"; "substr"; "strupr"; "strlwr"; "vstr" ]

and rhs t =
  let start = top t in
  let saved = t.context in
  t.context <- Some "#declare of a float, vector or colour";
  let d =
    Fun.protect ~finally:(fun () -> t.context <- saved) (fun () ->
        match string_without_semi t with
        | `String -> Decl.Value (Value.String (parse t Parser.Incremental.string_arg))
        | `Plain -> (
            match Quick.declare_value t with
            | Some d -> d
            | None ->
            (* POV-Ray: a float, vector or colour #declare ends with ';'
               since #version 3.5; before, the value ends where it can *)
            let missing = ref None in
            t.semi_probe <- Some missing;
            let old = Defaults.version () < 3.5 in
            if old then t.optional_sep <- Some Parser.SEMI;
            let d = parse t Parser.Incremental.declare_rhs in
            match (!missing, d) with
            | Some (found, loc), Decl.Value (Value.Float _ | Value.Vector _) ->
                if old then
                  Diag.warning loc "a float, vector or colour #declare should end with ';'"
                else
                  fail t loc
                    "expected an operator or ';', found %s (#declare of a float, vector or colour ends with ';')"
                    found;
                d
            | _ -> d)
        | `Bounded (f, i) -> (
            (* hand the parser the missing ';', then insist on a string *)
            let l = (Toks.get f.toks i).loc in
            t.stop_at <- Some (f, i);
            let d = Fun.protect ~finally:(fun () -> t.stop_at <- None) (fun () -> parse t Parser.Incremental.declare_rhs) in
            match d with
            | Decl.Value (Value.String _) -> d
            | _ ->
                fail t l "expected an operator or ';', found %s (#declare of a float, vector or colour ends with ';')"
                  (describe (Toks.get f.toks i).raw)))
  in
  (* layered textures: texture {...} texture {...}, the last on top *)
  let rec layers d =
    match d with
    | Decl.Texture below when t.pending = [] && (peek_past_ends t ~from:start).raw = Tok Parser.TEXTURE -> (
        let at = (peek_past_ends t ~from:start).loc in
        match parse t Parser.Incremental.declare_rhs with
        | Decl.Texture above -> (
            match Camlray.Texture.layering ~above ~below with
            | Some m -> fail t at "%s" m
            | None -> layers (Decl.Texture (above @ below)))
        | other -> other)
    | _ -> d
  in
  let d = layers d in
  (match d with
  | Decl.Value _ -> ()
  | _ when t.pending <> [] -> ()
  | _ -> ( match (peek_past_ends t ~from:start).raw with Tok Parser.SEMI -> ignore (raw_next t) | _ -> ()));
  d


let create config env ~file toks =
  let t = Cursor.create config env ~file toks in
  t.runner <- { run = (fun entry -> parse t entry) };
  t

(* The entry point: an unsupported feature met outside a #declare is an
   error like any other. *)
let parse t start = try parse t start with Unsupported_use (d, _) -> raise (Diag.Error d)

let find_readable t loc name =
  match find_file t name with
  | Some p ->
      allowed t loc p;
      Some p
  | None -> None

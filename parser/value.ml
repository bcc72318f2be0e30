open Camlray

type t = Float of float | Vector of float array | String of string

let type_name = function Float _ -> "a float" | Vector _ -> "a vector" | String _ -> "a string"

let to_string = function
  | Float f -> Printf.sprintf "%g" f
  | Vector a ->
      "<" ^ String.concat ", " (Array.to_list (Array.map (Printf.sprintf "%g") a)) ^ ">"
  | String s -> Printf.sprintf "%S" s

let expected loc what v = Diag.error loc "expected %s, found %s" what (type_name v)

let to_float loc = function
  | Float f -> f
  | v -> expected loc "a float" v

let comp a i = if i < Array.length a then a.(i) else 0.

let to_vec3 loc = function
  | Float f -> Vec3.make f f f
  | Vector a -> Vec3.make (comp a 0) (comp a 1) (comp a 2)
  | v -> expected loc "a vector" v

let to_vec5 = function
  | Float f -> Array.make 5 f
  | Vector a -> Array.init 5 (comp a)
  | String _ -> Array.make 5 0.

let to_color loc v =
  match v with
  | Float _ | Vector _ ->
      let a = to_vec5 v in
      Color.rgbft a.(0) a.(1) a.(2) a.(3) a.(4)
  | String _ -> expected loc "a colour" v

let to_rgb loc v = (to_color loc v).c

(* float -> int, an error where the float is no integer-sized number *)
let int_of loc f =
  if Float.is_nan f || Float.abs f > 1e15 then
    Diag.error loc "%g cannot be used as a whole number here" f
  else int_of_float f

let to_int loc v =
  let f = to_float loc v in
  if Float.abs (f -. Float.round f) < 1e-9 then int_of loc (Float.round f) else int_of loc f

let to_bool loc v = to_float loc v <> 0.

let to_string_value loc = function
  | String s -> s
  | v -> expected loc "a string" v

let bool b = Float (if b then 1. else 0.)

let arith loc op a b =
  let f = match op with
    | "+" -> ( +. ) | "-" -> ( -. ) | "*" -> ( *. ) | "/" -> ( /. )
    | _ -> assert false
  in
  (* POV-Ray warns and goes on *)
  let zero = function Float y -> y = 0. | Vector a -> Array.exists (( = ) 0.) a | String _ -> false in
  if op = "/" && zero b then Diag.warning loc "Divide by zero.";
  match (a, b) with
  | Float x, Float y -> Float (f x y)
  | Vector x, Float y -> Vector (Array.map (fun c -> f c y) x)
  | Float x, Vector y -> Vector (Array.map (fun c -> f x c) y)
  | Vector x, Vector y ->
      let n = max (Array.length x) (Array.length y) in
      Vector (Array.init n (fun i -> f (comp x i) (comp y i)))
  | String _, _ | _, String _ ->
      Diag.error loc "operator %s does not apply to strings" op

let binop loc op a b =
  match (op, a, b) with
  (* POV-Ray 3.7 compares two strings by their bytes (strcmp) *)
  | ("<" | "<=" | ">" | ">=" | "=" | "!="), String x, String y ->
      let c = String.compare x y in
      bool
        (match op with
        | "<" -> c < 0
        | "<=" -> c <= 0
        | ">" -> c > 0
        | ">=" -> c >= 0
        | "=" -> c = 0
        | _ -> c <> 0)
  | _ ->
  match op with
  | "+" | "-" | "*" | "/" -> arith loc op a b
  | "<" -> bool (to_float loc a < to_float loc b)
  | "<=" -> bool (to_float loc a <= to_float loc b)
  | ">" -> bool (to_float loc a > to_float loc b)
  | ">=" -> bool (to_float loc a >= to_float loc b)
  | "=" -> bool (Float.abs (to_float loc a -. to_float loc b) <= 1e-10)
  | "!=" -> bool (Float.abs (to_float loc a -. to_float loc b) > 1e-10)
  | "&" -> bool (to_bool loc a && to_bool loc b)
  | "|" -> bool (to_bool loc a || to_bool loc b)
  | _ -> Diag.error loc "unknown operator %s" op

let neg loc = function
  | Float f -> Float (-.f)
  | Vector a -> Vector (Array.map (fun c -> -.c) a)
  | v -> expected loc "a float or vector" v

let not_ loc v = bool (not (to_bool loc v))

let dot_member loc v m =
  let a = match v with
    | Float f -> [| f; f; f; f; f |]
    | Vector a -> a
    | String _ -> Diag.error loc "a string has no .%s" m
  in
  let get i =
    if i < Array.length a then Float a.(i)
    else Diag.error loc "this vector has %d components: .%s does not exist" (Array.length a) m
  in
  match m with
  | "x" | "u" | "red" -> get 0
  | "y" | "v" | "green" -> get 1
  | "z" | "blue" -> get 2
  | "t" | "filter" -> get 3
  | "transmit" -> get 4
  | "gray" | "grey" ->
      Float ((0.297 *. comp a 0) +. (0.589 *. comp a 1) +. (0.114 *. comp a 2))
  | _ -> Diag.error loc "unknown component .%s" m

let deg = 180. /. Float.pi

let vec3_value (v : Vec3.t) = Vector [| v.x; v.y; v.z |]

let functions =
  [ "sin"; "cos"; "tan"; "asin"; "acos"; "atan"; "atan2"; "sqrt"; "pow"; "exp"; "log"; "ln";
    "abs"; "min"; "max"; "mod"; "int"; "floor"; "ceil"; "div"; "radians"; "degrees"; "select";
    "vlength"; "vnormalize"; "vcross"; "vdot"; "vrotate"; "vaxis_rotate"; "vturbulence"; "concat"; "str"; "chr";
    "asc"; "strlen"; "substr"; "strupr"; "strlwr"; "val"; "strcmp"; "sinh"; "cosh"; "tanh";
    "asinh"; "acosh"; "atanh"; "sqr"; "bitwise_and"; "bitwise_or"; "bitwise_xor"; "vstr"; "seed"; "rand" ]

let is_function name = List.mem name functions

let format_float w d f =
  (* POV-Ray's str(): width w (0: none, negative: zero-padded), d digits
     (-1: default %f) *)
  let s = if d < 0 then Printf.sprintf "%f" f else Printf.sprintf "%.*f" d f in
  let pad = abs w - String.length s in
  if pad <= 0 then s
  else if w < 0 then
    if f < 0. then "-" ^ String.make pad '0' ^ String.sub s 1 (String.length s - 1)
    else String.make pad '0' ^ s
  else String.make pad ' ' ^ s

(* seed(n) makes a random stream and returns its number (0, 1, ... in
   order of creation); rand(stream) advances that stream. This is
   POV-Ray 3.7's generator (Parser::stream_seed, POV_rand): a 32-bit
   linear congruential generator, x <- x * 1812433253 + 12345 mod 2^32,
   returning x / (2^32 - 1), so scenes draw the same numbers as in
   POV-Ray. *)
let streams : (int, int ref) Hashtbl.t = Hashtbl.create 8
let stream_count = ref 0
let reset_streams () = Hashtbl.reset streams; stream_count := 0

(* out-of-range seeds become -2^31, as in povray *)
let seed_of_float f =
  if Float.is_nan f || f >= 2147483648. || f <= -2147483649. then -0x8000_0000
  else int_of_float f

let new_stream f =
  let s = seed_of_float f in
  let id = !stream_count in
  incr stream_count;
  Hashtbl.replace streams id (ref (s land 0xFFFFFFFF));
  float_of_int id

let rand loc id =
  match Hashtbl.find_opt streams (int_of loc id) with
  | None -> Diag.error loc "rand(%g): no such random stream (make one with seed())" id
  | Some st ->
      st := ((!st * 1812433253) + 12345) land 0xFFFFFFFF;
      float_of_int !st /. 4294967295.

let call loc name args =
  let f i = to_float loc (List.nth args i) in
  let v i = to_vec3 loc (List.nth args i) in
  let s i = to_string_value loc (List.nth args i) in
  let arity n =
    if List.length args <> n then
      Diag.error loc "%s expects %d argument%s, got %d" name n (if n = 1 then "" else "s")
        (List.length args)
  in
  let f1 g = arity 1; Float (g (f 0)) in
  let f2 g = arity 2; Float (g (f 0) (f 1)) in
  (* widths and digit counts: at most 100 (POV-Ray has no use for more) *)
  let small i = max (-100) (min 100 (int_of loc (f i))) in
  match name with
  | "sin" -> f1 Float.sin | "cos" -> f1 Float.cos | "tan" -> f1 Float.tan
  | "asin" | "acos" ->
      (* POV-Ray warns and clamps *)
      arity 1;
      let x = f 0 in
      if x < -1. || x > 1. then Diag.warning loc (Printf.sprintf "Domain error in %s." name);
      let x = Float.max (-1.) (Float.min 1. x) in
      Float (if name = "asin" then Float.asin x else Float.acos x)
  | "atan" -> f1 Float.atan | "atan2" -> f2 Float.atan2
  | "sinh" -> f1 Float.sinh | "cosh" -> f1 Float.cosh | "tanh" -> f1 Float.tanh
  | "asinh" -> f1 (fun x -> Float.log (x +. Float.sqrt ((x *. x) +. 1.)))
  | "acosh" -> f1 (fun x -> Float.log (x +. Float.sqrt ((x *. x) -. 1.)))
  | "atanh" -> f1 (fun x -> 0.5 *. Float.log ((1. +. x) /. (1. -. x)))
  | "sqrt" ->
      arity 1;
      if f 0 < 0. then Diag.error loc "sqrt of negative number %g" (f 0);
      Float (Float.sqrt (f 0))
  | "sqr" -> f1 (fun x -> x *. x)
  | "pow" -> f2 Float.pow | "exp" -> f1 Float.exp
  | "log" | "ln" ->
      arity 1;
      if f 0 <= 0. then Diag.error loc "%s of a number that is not positive: %g" name (f 0);
      Float (if name = "log" then Float.log10 (f 0) else Float.log (f 0))
  | "abs" -> f1 Float.abs
  | "floor" -> f1 Float.floor | "ceil" -> f1 Float.ceil
  | "int" -> f1 Float.trunc
  | "mod" -> f2 Float.rem
  | "div" -> f2 (fun a b -> Float.trunc (a /. b))
  | "radians" -> f1 (fun a -> a /. deg) | "degrees" -> f1 (fun a -> a *. deg)
  | "bitwise_and" -> f2 (fun a b -> float_of_int (int_of loc a land int_of loc b))
  | "bitwise_or" -> f2 (fun a b -> float_of_int (int_of loc a lor int_of loc b))
  | "bitwise_xor" -> f2 (fun a b -> float_of_int (int_of loc a lxor int_of loc b))
  | "min" | "max" ->
      if args = [] then Diag.error loc "%s needs at least one argument" name;
      let xs = List.map (to_float loc) args in
      Float (List.fold_left (if name = "min" then Float.min else Float.max) (List.hd xs) xs)
  | "select" -> (
      match args with
      | [ c; a; b ] -> if to_float loc c < 0. then a else b
      | [ c; a; b; d ] ->
          let x = to_float loc c in
          if x < 0. then a else if x = 0. then b else d
      | _ -> Diag.error loc "select expects 3 or 4 arguments, got %d" (List.length args))
  | "vlength" -> arity 1; Float (Vec3.length (v 0))
  | "vnormalize" -> arity 1; vec3_value (Vec3.normalize (v 0))
  | "vcross" -> arity 2; vec3_value (Vec3.cross (v 0) (v 1))
  | "vdot" -> arity 2; Float (Vec3.dot (v 0) (v 1))
  | "vrotate" -> arity 2; vec3_value (Transform.vector (Transform.rotate (v 1)) (v 0))
  | "vaxis_rotate" ->
      arity 3; vec3_value (Transform.vector (Transform.axis_rotate (v 1) (f 2)) (v 0))
  | "vturbulence" ->
      (* vturbulence(lambda, omega, octaves, V): POV-Ray's DTurbulence,
         sum over i < octaves of omega^i DNoise(lambda^i V), the octaves
         truncated and kept within 1 .. 10, lambda and omega rounded to
         single precision (POV-Ray keeps them in its turbulence's
         single-precision fields), as POV-Ray does *)
      arity 4;
      let octaves = Float.trunc (f 2) in
      let octaves = if octaves < 1. then 1 else if octaves > 10. then 10 else int_of_float octaves in
      let single = Camlray.Floats.single in
      let p = Vec3.m () and out = Vec3.m () in
      Vec3.load p (v 3);
      Noise.dturbulence ~octaves ~omega:(single (f 1)) ~lambda:(single (f 0)) p out;
      vec3_value (Vec3.of_m out)
  | "concat" -> String (String.concat "" (List.map (to_string_value loc) args))
  | "str" -> arity 3; String (format_float (small 1) (small 2) (f 0))
  | "vstr" ->
      arity 5;
      (* vstr(N, V, separator, width, digits) *)
      let n = int_of loc (f 0) in
      if n < 2 || n > 5 then Diag.error loc "vstr: the component count must be 2 to 5, found %d" n;
      let a = to_vec5 (List.nth args 1) in
      let w = small 3 and d = small 4 in
      String (String.concat (s 2) (List.init (max 0 (min 5 n)) (fun i -> format_float w d a.(i))))
  | "chr" -> arity 1;
      let c = int_of loc (f 0) in
      if c < 0 || c > 255 then Diag.error loc "chr(%d): code outside 0..255" c;
      String (String.make 1 (Char.chr c))
  | "asc" -> arity 1;
      let x = s 0 in Float (if x = "" then 0. else float_of_int (Char.code x.[0]))
  | "strlen" -> arity 1; Float (float_of_int (String.length (s 0)))
  | "substr" ->
      arity 3;
      let x = s 0 and p = int_of loc (f 1) and n = int_of loc (f 2) in
      if p < 1 || n < 0 || p - 1 + n > String.length x then
        Diag.error loc "substr(%S, %d, %d): outside the string" x p n;
      String (String.sub x (p - 1) n)
  | "strupr" -> arity 1; String (String.uppercase_ascii (s 0))
  | "strlwr" -> arity 1; String (String.lowercase_ascii (s 0))
  | "val" -> arity 1; (
      match float_of_string_opt (String.trim (s 0)) with
      | Some x -> Float x
      | None -> Float 0.)
  | "seed" -> arity 1; Float (new_stream (f 0))
  | "rand" -> arity 1; Float (rand loc (f 0))
  | "strcmp" -> arity 2; Float (float_of_int (compare (s 0) (s 1)))
  | _ -> Diag.error loc "%s is not a function camlray knows" name

(* global_settings' assumed_gamma as read so far (POV-Ray's working
   gamma: 1 until one is given) *)
let working_gamma = ref 1.

(* a linear value in the working gamma's space *)
let to_working c = if !working_gamma = 1. then c else Float.pow c (1. /. !working_gamma)

let srgb_decode c =
  to_working (if c <= 0.04045 then c /. 12.92 else Float.pow ((c +. 0.055) /. 1.055) 2.4)

let rgb_kind loc kw v =
  let need n =
    match v with
    | Float x -> Array.make n x
    | Vector a ->
        if Array.length a < n && Array.length a <> 3 then
          Diag.error loc "%s needs a vector of %d components, found %d" kw n (Array.length a);
        Array.init n (comp a)
    | String _ -> expected loc "a vector" v
  in
  let srgb = String.length kw > 1 && kw.[0] = 's' in
  let base = if srgb then String.sub kw 1 (String.length kw - 1) else kw in
  let a =
    match base with
    | "rgb" -> let a = need 3 in [| a.(0); a.(1); a.(2); 0.; 0. |]
    | "rgbf" -> let a = need 4 in [| a.(0); a.(1); a.(2); a.(3); 0. |]
    | "rgbt" -> let a = need 4 in [| a.(0); a.(1); a.(2); 0.; a.(3) |]
    | "rgbft" -> need 5
    | _ -> Diag.error loc "unknown colour keyword %s" kw
  in
  if srgb then for i = 0 to 2 do a.(i) <- srgb_decode a.(i) done;
  Vector a

let set_channel loc v ch x =
  let a = to_vec5 v in
  let i = match ch with
    | "red" -> 0 | "green" -> 1 | "blue" -> 2 | "filter" -> 3 | "transmit" -> 4
    | _ -> Diag.error loc "unknown colour channel %s" ch
  in
  a.(i) <- x;
  Vector a

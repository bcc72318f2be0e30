(* The lexer's numbers: most are converted without going through their
   text (digits times or over an exact power of ten, Clinger's fast
   path); every one must be the double float_of_string gives, bit for
   bit. *)
open Camlray_lang

let value text =
  match (Lexer.tokenize ~file:"<n>" text).(0).raw with
  | Lexer.Tok (Parser.FLOAT f) -> f
  | _ -> Alcotest.failf "%S did not lex as one number" text

let same text =
  let a = value text and b = float_of_string text in
  Int64.equal (Int64.bits_of_float a) (Int64.bits_of_float b)

let known () =
  List.iter
    (fun t -> if not (same t) then Alcotest.failf "%s: %h, float_of_string %h" t (value t) (float_of_string t))
    [ "0"; "000"; "0.0"; "1"; "5."; ".5"; "0.1"; "0.3"; "2.675"; "123456789012345"; "1234567890123456";
      "9007199254740993"; "0.000001"; "1e22"; "1e23"; "1e-22"; "1e-23"; "1.5E+3"; "4.9e-324"; "2.5e-320";
      "1e400"; "1e-400"; "00012.3400e-0002"; "1e00022"; "123456789012345678901234567890" ]

(* digits, an optional fraction, an optional exponent, as scenes write them *)
let number_text =
  let open QCheck.Gen in
  let digits lo hi = map (String.concat "") (list_size (int_range lo hi) (map string_of_int (int_range 0 9))) in
  let* whole = digits 0 18 in
  let* frac = option (digits (if whole = "" then 1 else 0) 18) in
  let whole, frac = if whole = "" && frac = None then ("0", None) else (whole, frac) in
  let* exp = option (pair (oneof_list [ "e"; "E"; "e-"; "e+"; "E-" ]) (digits 1 3)) in
  return
    (whole
    ^ (match frac with Some f -> "." ^ f | None -> "")
    ^ match exp with Some (e, d) -> e ^ d | None -> "")

let random =
  QCheck.Test.make ~count:5000 ~name:"a number lexes to float_of_string's double, bit for bit"
    (QCheck.make ~print:Fun.id number_text)
    same

let tests =
  ("lexer", [ Alcotest.test_case "numbers, known cases" `Quick known; QCheck_alcotest.to_alcotest random ])

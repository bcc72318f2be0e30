(* Parse.string never raises: random token soup (directives, braces,
   operators, keywords, identifiers) gives Ok or a located Error. *)
open Camlray_lang

let words =
  [| "#declare"; "#local"; "#if"; "#else"; "#end"; "#while"; "#for"; "#macro"; "#switch"; "#case";
     "#break"; "#include"; "#undef"; "#ifdef"; "#version"; "#debug"; "#fopen"; "#read"; "#write";
     "{"; "}"; "("; ")"; "["; "]"; "<"; ">"; ","; ";"; "="; "+"; "-"; "*"; "/"; "?"; ":"; "&"; "|";
     "!"; "."; "x"; "1"; "0.5"; "-2"; "\"s\""; "A"; "B"; "M"; "sphere"; "plane"; "pigment";
     "rgb"; "color"; "function"; "spline"; "array"; "array[2]"; "sin"; "concat"; "str"; "seed";
     "rand"; "camera"; "light_source"; "texture"; "finish"; "transform"; "rotate"; "scale";
     "defined"; "dimensions"; "version"; "clock"; "/*"; "*/"; "//"; "\n" |]

let gen =
  QCheck.Gen.(
    map (fun l -> String.concat " " l) (list_size (int_range 0 40) (map (Array.get words) (int_bound (Array.length words - 1)))))

let options =
  { Parse.default_options with
    limits = { Supplier.default_limits with max_loop_iterations = 200; max_macro_depth = 20 } }

let prop =
  QCheck.Test.make ~name:"random token soup: Ok or a located error, never an exception" ~count:1500
    (QCheck.make ~print:(fun s -> s) gen)
    (fun text ->
      match Parse.string ~options text with
      | Ok _ -> true
      | Error d -> d.Diag.msg <> "" && not (Scn.contains d.msg "internal error"))

let tests = ("parse", [ QCheck_alcotest.to_alcotest prop ])

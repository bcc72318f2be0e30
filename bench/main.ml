(* make bench: scene size against trace time (see bench.mli). Options:
   --smoke (tiny sizes, a seconds-long check), -j N (domains),
   --sizes 1000,1000000. *)
let () =
  let smoke = Array.mem "--smoke" Sys.argv in
  let domains =
    let rec find i = if i + 1 >= Array.length Sys.argv then 1
      else if Sys.argv.(i) = "-j" then int_of_string Sys.argv.(i + 1) else find (i + 1) in
    find 1
  in
  let sizes =
    let rec find i = if i + 1 >= Array.length Sys.argv then None
      else if Sys.argv.(i) = "--sizes" then
        Some (List.map int_of_string (String.split_on_char ',' Sys.argv.(i + 1)))
      else find (i + 1) in
    find 1
  in
  let rows =
    if smoke then Camlray_bench.Bench.run ~sizes:[ 10; 1000 ] ~width:64 ~height:48 ~domains ()
    else Camlray_bench.Bench.run ?sizes ~domains ()
  in
  Camlray_bench.Bench.print rows

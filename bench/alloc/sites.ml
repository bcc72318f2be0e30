(* Where a whitted render allocates: Gc.Memprof samples minor allocations
   (1 word in 100) during a one-domain render and ranks the call sites
   (the allocating function and its two callers) by words. With --parse,
   where parsing and compiling the scene allocate instead; with --mc SPP,
   a Monte Carlo render.
   Usage: sites.exe SCENE [-W n] [-H n] [--top n] [--parse] [--mc SPP] *)
open Camlray

let () =
  let w = ref 160 and h = ref 120 and top = ref 20 and file = ref "" and parse = ref false and mc = ref 0 in
  Arg.parse
    [ ("-W", Arg.Set_int w, "width"); ("-H", Arg.Set_int h, "height");
      ("--top", Arg.Set_int top, "N sites to show");
      ("--parse", Arg.Set parse, "rank the sites of parsing and compiling, not rendering");
      ("--mc", Arg.Set_int mc, "SPP rank the sites of a Monte Carlo render") ]
    (fun f -> file := f)
    "sites.exe SCENE";
  let words = Hashtbl.create 64 in
  let site (info : Gc.Memprof.allocation) =
    Printexc.raw_backtrace_to_string info.callstack
    |> String.split_on_char '\n'
    |> List.filter (fun l -> l <> "")
    |> List.filteri (fun i _ -> i < 3)
    |> String.concat "\n    <- "
  in
  let alloc_minor (info : Gc.Memprof.allocation) =
    let k = site info in
    let n = (info.size + 1) * info.n_samples in
    Hashtbl.replace words k (n + Option.value ~default:0 (Hashtbl.find_opt words k));
    None
  in
  let start () =
    ignore
      (Gc.Memprof.start ~sampling_rate:1e-2 ~callstack_size:8
         { Gc.Memprof.null_tracker with alloc_minor } : Gc.Memprof.t)
  in
  let report () =
    Gc.Memprof.stop ();
    let sites = Hashtbl.fold (fun k v acc -> (v, k) :: acc) words [] |> List.sort compare |> List.rev in
    let total = List.fold_left (fun a (v, _) -> a + v) 0 sites in
    List.iteri
      (fun i (v, k) -> if i < !top then Printf.printf "%5.1f%%  %s\n" (100. *. float v /. float total) k)
      sites
  in
  if !parse then start ();
  let scene = match Measured.load !file with Error msg -> prerr_string msg; exit 1 | Ok s -> s in
  if !parse then (report (); exit 0);
  let width = !w and height = !h in
  let pixel = Measured.pixel scene ~width ~height ~mc:!mc in
  (* a first render makes the domain's scratch (each object's included):
     the second shows what every ray allocates *)
  ignore (Render.image_into ~domains:1 ~width ~height pixel);
  start ();
  ignore (Render.image_into ~domains:1 ~width ~height pixel);
  report ()

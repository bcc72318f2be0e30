type options = {
  include_dirs : string list;
  limits : Supplier.limits;
  clock : float;
  image_width : int;
  image_height : int;
  frame_number : int;
  allow_read : string list;
  confine_reads : bool;
  fold_arithmetic : bool;
  quick_eval : bool;
}

let default_options =
  { include_dirs = []; limits = Supplier.default_limits; clock = 0.; image_width = 800;
    image_height = 600; frame_number = 0; allow_read = []; confine_reads = true;
    fold_arithmetic = true; quick_eval = true }

let pov_include_dir = "/usr/share/povray-3.7/include"

(* where Debian's povray puts the fonts its include folder links to *)
let pov_font_dir = "/usr/share/fonts/truetype/povray"

let run options ~name text =
  Defaults.reset ();
  Shapes.forget_textures ();
  Budget.reset options.limits.max_objects;
  Value.reset_streams ();
  Probe.reset ();
  let last_loc = ref Loc.none in
  try
    let toks = Toks.of_text ~file:name text in
    last_loc := (Toks.get toks 0).loc;
    let include_dirs =
      options.include_dirs
      @ if Sys.file_exists pov_include_dir then [ pov_include_dir ] else []
    in
    let access =
      if options.confine_reads then
        Access.create
          (Sys.getcwd () :: Filename.dirname name
          :: (include_dirs @ options.allow_read
             @ if Sys.file_exists pov_font_dir then [ pov_font_dir ] else []))
      else Access.unrestricted
    in
    let config =
      {
        Supplier.include_dirs;
        access;
        fold = options.fold_arithmetic;
        quick = options.quick_eval;
        limits = options.limits;
        builtins =
          [ ("clock", options.clock); ("image_width", float_of_int options.image_width);
            ("image_height", float_of_int options.image_height);
            ("frame_number", float_of_int options.frame_number);
            ("clock_delta", 0.); ("clock_on", 0.); ("initial_frame", 0.); ("final_frame", 0.);
            ("initial_clock", 0.); ("final_clock", 0.) ];
      }
    in
    let sup = Supplier.create config (Env.create ()) ~file:name toks in
    Defaults.set_finder (Supplier.find_readable sup);
    let items =
      Fun.protect ~finally:(fun () -> Supplier.close_files sup) (fun () ->
          Supplier.parse sup Parser.Incremental.scene)
    in
    let scene = { Sdl.items; version = Defaults.first_version (); file = name } in
    Ok (scene, Supplier.files_read sup)
  with
  | Diag.Error d -> Error d
  | Stack_overflow ->
      Error { Diag.loc = !last_loc; msg = "the scene nests too deeply (stack overflow)"; chain = [] }
  | Out_of_memory -> Error { Diag.loc = !last_loc; msg = "out of memory while parsing"; chain = [] }
  | (Failure m | Invalid_argument m | Sys_error m) ->
      Error { Diag.loc = !last_loc; msg = "internal error while parsing: " ^ m; chain = [] }
  | Division_by_zero -> Error { Diag.loc = !last_loc; msg = "division by zero"; chain = [] }

let file ?(options = default_options) path =
  match In_channel.with_open_bin path In_channel.input_all with
  | text -> run options ~name:path text
  | exception Sys_error e -> Error { Diag.loc = Loc.none; msg = e; chain = [] }

let string ?(options = default_options) ?(name = "<string>") text =
  Result.map fst (run options ~name text)

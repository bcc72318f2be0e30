(* One test executable, one alcotest run: every suite is listed here. *)
let () =
  Alcotest.run "camlray"
    [
      Test_vec3.tests;
      Test_transform.tests;
      Test_hits.tests;
      Test_camera.tests;
      Test_render.tests;
      Test_cli.tests;
      Test_pov_scenes.tests;
      Test_image.tests;
      Test_sampler.tests;
      Test_bsdf.tests;
      Test_path.tests;
    ]

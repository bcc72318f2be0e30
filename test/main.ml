(* One test executable, one alcotest run: every suite is listed here. *)
let () =
  Alcotest.run "camlray"
    [
      Test_vec3.tests;
      Test_image.tests;
      Test_shape.tests;
      Test_bvh.tests;
      Test_object.tests;
      Test_geom_render.tests;
      Test_bench.tests;
    ]

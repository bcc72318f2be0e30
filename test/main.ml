(* One test executable, one alcotest run: every suite is listed here. *)
let () =
  Alcotest.run "camlray"
    [
      Test_vec3.tests;
      Test_image.tests;
      Test_whitted.tests;
      Test_light.tests;
      Test_pattern.tests;
      Test_aa.tests;
      Test_gamma.tests;
      Test_compare.tests;
    ]

// A box room lit by one light, its walls lighting each other by radiosity
// (POV-Ray 3.7: ambient gives way to the gathered light). Flagged as noise
// by camlray compare: the gathers agree with POV-Ray statistically
#version 3.7;
global_settings { assumed_gamma 1 radiosity { count 60 recursion_limit 2 error_bound 1 nearest_count 5 } }
camera { location <0, 1.5, -3.4> look_at <0, 1.2, 0> angle 60 }
light_source { <0, 2.8, 0.2> rgb 0.9 }
#declare W = finish { diffuse 0.8 ambient 0 }
box { <-1.5, 0, -3.5>, <1.5, 3, 1.5> hollow pigment { rgb 0.8 } finish { W } }
box { <-1.51, 0.01, -3.4>, <-1.49, 2.99, 1.49> pigment { rgb <0.8, 0.15, 0.1> } finish { W } }
box { <1.49, 0.01, -3.4>, <1.51, 2.99, 1.49> pigment { rgb <0.1, 0.6, 0.15> } finish { W } }
box { <-0.9, 0, 0>, <-0.2, 1.1, 0.7> rotate y * 20 pigment { rgb 0.8 } finish { W } }
sphere { <0.6, 0.45, -0.4>, 0.45 pigment { rgb <0.3, 0.4, 0.9> } finish { W phong 0.5 } }

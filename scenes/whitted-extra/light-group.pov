// light_group: lights that light only the objects of their group.
// Left, a group without global_lights: its red light alone lights the
// box and the sphere on it (the floor's light does not), and a bar
// outside the group shadows it. Middle, a declared group placed twice,
// turned and moved (its blue light moves with it), global_lights on.
// Right, the manual's CSG example: a difference of two groups, the
// sphere lit red, the cut lit green. Groups cast shadows of the global
// light on the floor like any object.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 5, -11> look_at <0, 0.8, 0> angle 55 }
light_source { <-3, 10, -6> rgb 0.9 }
background { rgb <0.1, 0.12, 0.18> }
plane { y, 0 pigment { checker rgb 0.75 rgb 0.45 } }

light_group {
  light_source { <-4.5, 9, -4> rgb <1, 0.35, 0.25> }
  box { <-4.4, 0, -0.6>, <-3.2, 1, 0.6> pigment { rgb 0.9 } }
  sphere { <-3.8, 1.55, 0>, 0.55 pigment { rgb <0.9, 0.9, 0.6> } finish { phong 0.5 } }
}
// outside the group: lit by the global light only, yet it shadows the
// group from the group's light
box { <-5, 3, -1.4>, <-2.6, 3.15, -1.15> pigment { rgb <0.4, 0.8, 0.4> } }

#declare Pair = light_group {
  light_source { <0, 2.5, -2.5> rgb <0.3, 0.45, 1> }
  cylinder { <0, 0, 0>, <0, 1.2, 0>, 0.45 pigment { rgb 0.85 } }
  torus { 0.5, 0.14 translate 1.35*y pigment { rgb <1, 0.7, 0.3> } }
  global_lights on
}
object { Pair rotate 20*y translate <-0.9, 0, 0.4> }
object { Pair rotate -35*y translate <0.9, 0, -0.6> }

difference {
  light_group {
    sphere { 0, 1 pigment { rgb 1 } }
    light_source { <-100, 0, -100> rgb <1, 0.2, 0.2> }
    global_lights off
  }
  light_group {
    sphere { <0, 1, 0>, 1 pigment { rgb 1 } }
    light_source { <100, 100, 0> rgb <0.2, 1, 0.2> }
    global_lights off
  }
  rotate <-45, 0, 0> rotate -40*y
  translate <3.6, 1, 0.3>
}

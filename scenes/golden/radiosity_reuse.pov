// golden-args: --block-mean 8 --max-rmse 0.03 --fail 0.02 --max-bad-fraction 0
// Radiosity's reuse settings away from their defaults: a tighter reuse window
// (minimum_reuse, maximum_reuse), a lower pretrace error (low_error_factor), sampling in
// the final render too (always_sample on), and a block that asks for half the sample
// rays (radiosity { importance }). The Cornell-like box of radiosity_cornell, with 100
// rays a sample (POV-Ray differs from run to run: fewer rays leave it noisier).
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity { count 100 minimum_reuse 0.01 maximum_reuse 0.1 low_error_factor 0.3 always_sample on }
}
camera { location <0, 1, -0.98> look_at <0, 0.9, 0> angle 75 }
light_source { <0, 1.9, -0.3> color rgb 1 }
#declare White = finish { diffuse 0.8 ambient 0.3 };
box { <-1, 0, -1>, <1, 2, 1> inverse pigment { rgb 0.9 } finish { White } }
box { <-1.01, -0.01, -1>, <-0.999, 2.01, 1> pigment { rgb <0.8, 0.1, 0.1> } finish { White } }
box { <0.999, -0.01, -1>, <1.01, 2.01, 1> pigment { rgb <0.1, 0.7, 0.1> } finish { White } }
box { <-0.3, 0, -0.3>, <0.3, 1.2, 0.3> rotate y * 20 translate <-0.35, 0, 0.3>
      pigment { rgb 0.9 } finish { White } radiosity { importance 0.5 } }
box { <-0.3, 0, -0.3>, <0.3, 0.6, 0.3> rotate y * -20 translate <0.4, 0, -0.3>
      pigment { rgb 0.9 } finish { White } }

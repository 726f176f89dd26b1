// Phong lighting of isosurfaces (and shaded volume colours) from the vtkVolumeProperty's
// coefficients and the renderer's first light; two-sided. Shared by the mappers' fragment shaders
// (marker //UV::Phong); the uniforms are set by uvgl::SetPhongUniforms (vtkUnstructuredVolumeOpenGL.h).
uniform vec3 lightDirection; // eye space, towards the light
uniform vec3 lightColor;
uniform float ambient;
uniform float diffuse;
uniform float specular;
uniform float specularPower;

/// `color` lit with normal along `gradient` (any length, eye space), seen along `toEye` (unit).
vec3 Light(vec3 color, vec3 gradient, vec3 toEye)
{
  float length2 = dot(gradient, gradient);
  if (!(length2 > 0.0))
  {
    return color * (ambient + diffuse); // no direction to light by: as if facing the light
  }
  vec3 n = gradient * inversesqrt(length2);
  n = dot(n, toEye) < 0.0 ? -n : n; // two-sided
  float lambert = max(dot(n, lightDirection), 0.0);
  vec3 reflected = reflect(-lightDirection, n);
  float highlight = lambert > 0.0 ? pow(max(dot(reflected, toEye), 0.0), specularPower) : 0.0;
  return color * (ambient + diffuse * lambert) * lightColor + specular * highlight * lightColor;
}

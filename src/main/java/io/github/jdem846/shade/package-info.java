/**
 * Hillshade: the article's illumination of each cell by the angle between its surface normal and the light
 * (jDem846's method), and gdaldem's Horn, multidirectional, combined and igor methods, chosen with
 * {@link io.github.jdem846.shade.HillshadeMethod} and tuned with {@link io.github.jdem846.shade.HillshadeOptions}.
 */
package io.github.jdem846.shade;

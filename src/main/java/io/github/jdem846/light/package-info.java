/**
 * The direction light comes from ({@link io.github.jdem846.light.LightDirection}: azimuth and elevation) and a light
 * over a grid ({@link io.github.jdem846.light.LightField}: one direction everywhere, or one per place for a real sun).
 */
package io.github.jdem846.light;

/**
 * Small numeric and format helpers shared across packages (clamping, brightness, GeoTIFF key numbers). Internal: not
 * exported by the module.
 */
package io.github.jdem846.internal;

/**
 * Vector overlays: lines, polygons and points from a GeoJSON file or an ESRI shapefile drawn onto a rendered
 * picture ({@link io.github.jdem846.overlay.OverlayPainter}), after their coordinates are transformed into the
 * picture's CRS with Apache SIS.
 */
package io.github.jdem846.overlay;

/**
 * Draped images: a georeferenced picture (an 8-bit RGB or RGBA GeoTIFF, or a PNG or JPEG with a world file) laid
 * over the tint of a relief, cell by cell, before the light, as the original jDem846's image layers were ({@link
 * io.github.jdem846.drape.Drape}, {@link io.github.jdem846.render.Scene#withDrape}).
 */
package io.github.jdem846.drape;

/**
 * Web-map tile pyramids of a DEM: 256 × 256 PNG tiles in Web Mercator (EPSG:3857) in the XYZ scheme, for a range of
 * zoom levels, written as a {@code z/x/y.png} directory or one PMTiles v3 archive. {@link
 * io.github.jdem846.tiles.TileJob} renders each tile at its own resolution from the DEM (never by shrinking
 * pictures), with slopes and shadow lengths in ground metres; {@link io.github.jdem846.tiles.WebMercatorTile} is the
 * tile arithmetic (bounds in metres and degrees, the tile of a point).
 */
package io.github.jdem846.tiles;

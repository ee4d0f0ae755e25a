package io.github.jdem846.tiles;

import java.io.IOException;

/**
 * Where finished tiles go. {@link #write} may be called from several threads at once; nothing is visible at the
 * final path before {@link #commit}, and {@link #close} without a commit removes everything written.
 */
interface TileSink extends AutoCloseable {

    /** Takes one encoded tile. */
    void write(WebMercatorTile tile, byte[] png) throws IOException;

    /** Moves the finished tile set into place. */
    void commit(TileSetInfo info) throws IOException;

    /** Deletes whatever was staged and not committed. */
    @Override
    void close() throws IOException;

    /**
     * What the archive's header and metadata say about the tile set.
     *
     * @param name        a name for it (the DEM's file name)
     * @param description one line: how it was made
     * @param zooms       the zoom levels asked for
     * @param bounds      the DEM's latitude/longitude box
     */
    record TileSetInfo(String name, String description, ZoomRange zooms, io.github.jdem846.geo.LatLonBox bounds) {
    }
}

package io.github.jdem846.tiles;

import io.github.jdem846.geo.LatLonBox;
import io.github.jdem846.internal.IoMessages;
import java.io.IOException;
import java.nio.file.Path;

/**
 * Where finished tiles go: a {@code z/x/y.png} directory or a PMTiles archive. {@link #write} may be called from
 * several threads at once and in any order (the archive comes out the same); nothing is visible at the final path
 * before {@link #commit}, and {@link #close} without a commit removes everything written.
 */
public interface TileSink extends AutoCloseable {

    /**
     * Opens the sink {@link TileFormat#of} {@code output} names: a {@code .pmtiles} archive, or else a directory
     * that does not exist yet or is empty.
     *
     * @param output the {@code .pmtiles} file or the directory
     * @return the open sink
     * @throws IOException              when the output cannot be written there (naming it and why)
     * @throws IllegalArgumentException for a format that is not written ({@code .mbtiles})
     */
    static TileSink open(Path output) throws IOException {
        TileFormat format = TileFormat.of(output);
        try {
            return new FailureNamingSink(format == TileFormat.PMTILES ? new PmTilesSink(output)
                    : new DirectorySink(output), output);
        } catch (IOException e) {
            throw IoMessages.naming(e, output);
        }
    }

    /**
     * Takes one encoded tile.
     *
     * @param tile where the tile goes
     * @param png the whole PNG file
     * @throws IOException when it cannot be written
     */
    void write(WebMercatorTile tile, byte[] png) throws IOException;

    /**
     * Moves the finished tile set into place.
     *
     * @param info the name, description, zooms and bounds of the set (the archive keeps them in its metadata)
     * @throws IOException when the set cannot be moved into place
     */
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
    record TileSetInfo(String name, String description, ZoomRange zooms, LatLonBox bounds) {
    }
}

package io.github.jdem846.tiles;

import java.nio.file.Path;
import java.util.List;

/**
 * What a {@link TileJob} wrote.
 *
 * @param output  the directory or archive
 * @param format  how the tiles were stored
 * @param zooms   per zoom level, in order: the tiles considered and the tiles written
 * @param bytes   the PNG bytes of all tiles written (before deduplication in an archive)
 */
public record TileReport(Path output, TileFormat format, List<Zoom> zooms, long bytes) {

    /**
     * One zoom level.
     *
     * @param z          the zoom
     * @param range      the tiles that overlap the DEM's latitude/longitude box
     * @param written    tiles written (those holding data)
     * @param decimation the DEM's cells averaged per block for this zoom (1 = full resolution)
     */
    public record Zoom(int z, TileRange range, long written, int decimation) {

        /** {@return tiles of the range left out because no pixel of theirs holds data} */
        public long empty() {
            return range.count() - written;
        }
    }

    /**
     * Copies the list of zooms.
     *
     * @param output the directory or archive
     * @param format how the tiles were stored
     * @param zooms per zoom level, in order: the tiles considered and the tiles written
     * @param bytes the PNG bytes of all tiles written (before deduplication in an archive)
     */
    public TileReport {
        zooms = List.copyOf(zooms);
    }

    /** {@return tiles written at all zooms} */
    public long written() {
        return zooms.stream().mapToLong(Zoom::written).sum();
    }

    /** {@return tiles left out as empty at all zooms} */
    public long empty() {
        return zooms.stream().mapToLong(Zoom::empty).sum();
    }
}

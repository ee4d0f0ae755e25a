package io.github.jdem846.output;

import io.github.jdem846.output.TiffDirectory.Field;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.LongConsumer;

/**
 * A Cloud-Optimized GeoTIFF (COG), written band of rows after band of rows ({@link BandEncoder}): square tiles
 * ({@link WriteOptions#cogTileSize()}, 512 by default), Deflate with the horizontal predictor, the tags of
 * {@link GeoTiffTags}, and overviews each half the size of the one before, rounded down, until the smallest fits in
 * one tile, as many and as large as GDAL's COG driver makes them ({@link OverviewPyramid}: box averages of the
 * full-resolution pixels, where GDAL's default is cubic resampling). Only 8-bit gray and RGBA.
 *
 * <p>The file has GDAL's COG layout, and says so in GDAL's "ghost" structural metadata right after the header,
 * which makes {@code gdalinfo} report {@code LAYOUT=COG}: {@code LAYOUT=IFDS_BEFORE_DATA} (the IFDs of all levels,
 * full resolution first, and their tile offsets and sizes, come before any tile), {@code BLOCK_ORDER=ROW_MAJOR}
 * (the tiles of a level in row-major order; the smallest overview's tiles first, the full resolution's last),
 * {@code BLOCK_LEADER=SIZE_AS_UINT4} and {@code BLOCK_TRAILER=LAST_4_BYTES_REPEATED} (each tile preceded by its
 * size and followed by its last 4 bytes again, {@link TileStore}), {@code KNOWN_INCOMPATIBLE_EDITION=NO}.
 *
 * <p>Streaming: as bands arrive, every level's completed tile rows are compressed (the tiles of a band in
 * parallel when asked) into a scratch file per level next to the target ({@link TileStore}), the full resolution
 * from the bands, the overviews from rows reduced on the fly. Memory: the band, a tile row of every level (the rows
 * a band leaves unfinished) and one batch of compressed tiles. {@link #finish()} then writes the header, the ghost
 * block and the IFDs, and copies the stores after them, smallest level first.
 *
 * <p><b>BigTIFF.</b> Nothing of the file is written before {@link #finish()}, when the size of every tile is known:
 * the file is a classic TIFF when it fits in 4 GiB, else a BigTIFF (version 43, 8-byte offsets, LONG8 TileOffsets
 * and TileByteCounts). The choice is exact here, unlike for strips ({@link GeoTiffWriter}), which are written in
 * place as they come.
 */
final class CogWriter implements BandEncoder {

    /** Creates the scratch files of the levels. */
    @FunctionalInterface
    interface Scratch {
        Path create(String name) throws IOException;
    }

    /** Tiles compressed at once per processor, and at most. */
    private static final int TILES_PER_BATCH_AND_PROCESSOR = 4;
    private static final int MAX_TILES_PER_BATCH = 64;

    /** GDAL's structural metadata: what the layout promises (GDAL's COG driver writes the same block). */
    static final String GHOST = "LAYOUT=IFDS_BEFORE_DATA\n"
            + "BLOCK_ORDER=ROW_MAJOR\n"
            + "BLOCK_LEADER=SIZE_AS_UINT4\n"
            + "BLOCK_TRAILER=LAST_4_BYTES_REPEATED\n"
            + "KNOWN_INCOMPATIBLE_EDITION=NO\n"
            + " ";

    private final Path file;
    private final int samplesPerPixel;
    private final int tileSize;
    private final boolean parallel;
    private final long classicLimit;
    private final GeoReference geo;
    private final Double noData;
    private final List<Level> levels = new ArrayList<>();
    private final TiffBlocks blocks = new TiffBlocks();
    private final OverviewPyramid pyramid;
    private final byte[] row;
    private boolean finished;
    private LongConsumer encoded = rows -> { };

    /** One level: its size, its tile rows and the store of its tiles. */
    private final class Level {
        final int width;
        final int height;
        final int tilesAcross;
        final RowChunks tileRows;
        final TileStore store;

        Level(int width, int height, TileStore store) {
            this.width = width;
            this.height = height;
            this.tilesAcross = RowChunks.count(width, tileSize);
            this.store = store;
            this.tileRows = new RowChunks(width, height, samplesPerPixel, 8, tileSize, false, this::writeTiles);
        }

        /** The tiles of the tile rows a band completed, compressed a batch at a time and stored in order. */
        private void writeTiles(List<RowChunks.Chunk> ready) throws IOException {
            int batch = Batches.size(parallel, TILES_PER_BATCH_AND_PROCESSOR, MAX_TILES_PER_BATCH);
            int[] stored = {0};
            Batches.run(ready.size() * tilesAcross, batch, parallel,
                    i -> tile(ready.get(i / tilesAcross), i % tilesAcross), tile -> {
                        store.add(tile);
                        if (++stored[0] % tilesAcross == 0) {
                            encoded.accept(ready.get(stored[0] / tilesAcross - 1).rows());
                        }
                    });
        }

        /** Tile {@code tx} of a tile row: full size, zeros past the image's edges. */
        private byte[] tile(RowChunks.Chunk tileRow, int tx) {
            int x0 = tx * tileSize;
            int across = Math.min(tileSize, width - x0);
            int tileRowBytes = tileSize * samplesPerPixel;
            byte[] raw = new byte[tileSize * tileRowBytes];
            for (int r = 0; r < tileRow.rows(); r++) {
                tileRow.row(r, x0, across, raw, r * tileRowBytes);
            }
            return blocks.deflate(raw, tileSize, tileRowBytes, samplesPerPixel, true);
        }
    }

    /**
     * Starts a COG to be written to {@code file} at {@link #finish()}.
     *
     * @param scratch         where the levels' tiles wait
     * @param samplesPerPixel 4 (RGBA) or 1 (gray), 8 bits each
     * @param geo             the georeferencing, or {@code null}
     * @param noData          the GDAL_NODATA value (an integer 0..255 left out of the overviews), or {@code null}
     * @param tileSize        tile edge, a multiple of 16
     * @param parallel        compress the tiles of a band on all processors (the file is the same)
     * @param classicLimit    the largest file written as a classic TIFF ({@link TiffDirectory#CLASSIC_LIMIT};
     *                        smaller in tests)
     */
    CogWriter(Path file, Scratch scratch, int width, int height, int samplesPerPixel, GeoReference geo,
              Double noData, int tileSize, boolean parallel, long classicLimit) throws IOException {
        if (tileSize < 16 || tileSize % 16 != 0) {
            throw new IllegalArgumentException("COG tiles must be a multiple of 16 pixels, got " + tileSize);
        }
        this.file = file;
        this.samplesPerPixel = samplesPerPixel;
        this.tileSize = tileSize;
        this.parallel = parallel;
        this.classicLimit = classicLimit;
        this.geo = geo;
        this.noData = noData;
        this.row = new byte[Pixels.rowBytes(width, samplesPerPixel, 8)];
        int overviews = overviewCount(width, height, tileSize);
        try {
            int w = width;
            int h = height;
            for (int k = 0; k <= overviews; k++) {
                int tiles = Math.multiplyExact(RowChunks.count(w, tileSize), RowChunks.count(h, tileSize));
                levels.add(new Level(w, h, new TileStore(scratch.create("level" + k), tiles)));
                w = OverviewPyramid.half(w);
                h = OverviewPyramid.half(h);
            }
        } catch (IOException | RuntimeException e) {
            close();
            throw e;
        }
        this.pyramid = new OverviewPyramid(width, height, overviews, samplesPerPixel,
                noData == null ? null : (int) (double) noData, (k, r) -> levels.get(k).tileRows.append(r));
    }

    /**
     * The number of overview levels: halving ({@link OverviewPyramid#half}) until the picture fits in one tile, as
     * GDAL's COG driver counts them by default.
     */
    static int overviewCount(int width, int height, int tileSize) {
        int count = 0;
        for (int w = width, h = height; w > tileSize || h > tileSize; w = OverviewPyramid.half(w),
                h = OverviewPyramid.half(h)) {
            count++;
        }
        return count;
    }

    @Override
    public void append(Pixels band) throws IOException {
        if (finished) {
            throw new IllegalStateException("the COG is finished");
        }
        Level full = levels.get(0);
        full.tileRows.append(band);
        for (int y = 0; y < band.height() && levels.size() > 1; y++) {
            band.row(y, row, 0);
            pyramid.add(row, full.width);
        }
    }

    /** Writes the header, the ghost block, the IFDs and the tiles of every level, smallest level first. */
    @Override
    public void finish() throws IOException {
        Level full = levels.get(0);
        if (full.tileRows.rowsIn() != full.height) {
            throw new IllegalStateException("only " + full.tileRows.rowsIn() + " of " + full.height
                    + " rows were appended");
        }
        if (finished) {
            return;
        }
        for (Level level : levels) {
            if (!level.store.isComplete() || !pyramid.isComplete()) {
                throw new IllegalStateException("a COG level is missing tiles");
            }
        }
        List<TiffDirectory> directories = new ArrayList<>();
        for (int k = 0; k < levels.size(); k++) {
            directories.add(directory(k));
        }
        boolean big = placeTiles(directories, false) > classicLimit;
        if (big) {
            placeTiles(directories, true);
        }
        byte[] ghost = ghost();
        int header = big ? TiffDirectory.BIG_HEADER_BYTES : TiffDirectory.CLASSIC_HEADER_BYTES;
        try (FileChannel out = FileChannel.open(file, StandardOpenOption.WRITE, StandardOpenOption.CREATE,
                StandardOpenOption.TRUNCATE_EXISTING)) {
            long at = TiffDirectory.align(header + ghost.length);
            FileChannels.writeFully(out, TiffDirectory.header(big, at), 0);
            FileChannels.writeFully(out, ByteBuffer.wrap(ghost), header);
            for (int k = 0; k < directories.size(); k++) {
                TiffDirectory d = directories.get(k);
                long next = k + 1 < directories.size() ? at + d.size(big) : 0;
                FileChannels.writeFully(out, d.layOut(at, next, big), at);
                at += d.size(big);
            }
            for (int k = levels.size() - 1; k >= 0; k--) {
                levels.get(k).store.copyTo(out, at);
                at += levels.get(k).store.size();
            }
        }
        finished = true;
    }

    @Override
    public long rowsToEncode() {
        long rows = 0;
        for (Level level : levels) {
            rows += level.height;
        }
        return rows;
    }

    @Override
    public void onEncoded(LongConsumer rows) {
        encoded = java.util.Objects.requireNonNull(rows, "rows");
    }

    /** Deletes the scratch files. */
    @Override
    public void close() throws IOException {
        blocks.end();
        IOException failure = null;
        for (Level level : levels) {
            try {
                level.store.close();
            } catch (IOException e) {
                failure = failure == null ? e : failure;
            }
        }
        if (failure != null) {
            throw failure;
        }
    }

    /** The IFD of level {@code k}, tile offsets still to be placed. */
    private TiffDirectory directory(int k) {
        Level level = levels.get(k);
        TiffDirectory d = GeoTiffTags.samples(level.width, level.height, samplesPerPixel, 8, noData);
        if (k == 0) {
            GeoTiffTags.describe(d, geo, level.width, level.height);
        } else {
            d.put(254, Field.longs(1));                                   // NewSubfileType: reduced resolution
        }
        d.put(322, Field.longs(tileSize));                                // TileWidth
        d.put(323, Field.longs(tileSize));                                // TileLength
        return d;
    }

    /**
     * Sets each IFD's TileOffsets and TileByteCounts for the file {@link #finish()} writes, classic or BigTIFF.
     *
     * @return the size of that file
     */
    private long placeTiles(List<TiffDirectory> directories, boolean asBig) {
        for (int k = 0; k < levels.size(); k++) {   // sizes first: they do not depend on the offsets' values
            TiffDirectory d = directories.get(k);
            long[] counts = levels.get(k).store.counts();
            d.put(324, Field.offsets(new long[counts.length], asBig));
            d.put(325, Field.offsets(counts, asBig));
        }
        long at = TiffDirectory.align((asBig ? TiffDirectory.BIG_HEADER_BYTES : TiffDirectory.CLASSIC_HEADER_BYTES)
                + ghost().length);
        for (TiffDirectory d : directories) {
            at += d.size(asBig);
        }
        for (int k = levels.size() - 1; k >= 0; k--) {
            TileStore store = levels.get(k).store;
            directories.get(k).put(324, Field.offsets(store.offsets(at), asBig));
            at += store.size();
        }
        return at;
    }

    /** "GDAL_STRUCTURAL_METADATA_SIZE=000140 bytes\n" and the block: what GDAL looks for after the header. */
    static byte[] ghost() {
        String text = String.format(Locale.ROOT, "GDAL_STRUCTURAL_METADATA_SIZE=%06d bytes\n", GHOST.length()) + GHOST;
        return text.getBytes(StandardCharsets.US_ASCII);
    }
}

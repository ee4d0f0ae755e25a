package io.github.jdem846.io.geotiff;

import io.github.jdem846.io.DemFormatException;
import io.github.jdem846.io.source.MemoryGuard;
import java.nio.file.Path;

/**
 * The strips or tiles of a TIFF image directory, checked before any of them is read: TileWidth, TileLength and
 * RowsPerStrip of at least 1, as many offsets (and byte counts, when there are any) as the image has blocks, and
 * every block inside the file. A corrupt directory (a negative SLONG, a flipped type bit, a count past the end) is
 * refused with the tag, the value and the file's name, rather than failing later in a read.
 *
 * @param tiled       tiles rather than strips
 * @param blockWidth  tile width, or the image width for strips
 * @param blockHeight tile length, or rows per strip (at most the image height)
 * @param offsets     the StripOffsets or TileOffsets
 * @param byteCounts  the StripByteCounts or TileByteCounts (empty when the file has none)
 */
record TiffBlocks(boolean tiled, int blockWidth, int blockHeight, long[] offsets, long[] byteCounts) {

    /** Reads and checks the block structure of an image of {@code width × height} in a file of {@code fileSize}. */
    static TiffBlocks of(Path tif, TiffFields f, int width, int height, long fileSize) throws DemFormatException {
        if (width < 1 || height < 1) {
            throw new DemFormatException(tif, "the TIFF image is " + width + " × " + height + " cells (ImageWidth"
                    + " and ImageLength, TIFF tags 256 and 257); both must be at least 1");
        }
        boolean tiled = f.has(TiffFields.TILE_OFFSETS);
        int blockWidth;
        int blockHeight;
        if (tiled) {
            blockWidth = dimension(tif, f, TiffFields.TILE_WIDTH, "TileWidth");
            blockHeight = dimension(tif, f, TiffFields.TILE_LENGTH, "TileLength");
        } else {
            // absent: one strip (the TIFF default, 2³² − 1)
            long rows = f.has(TiffFields.ROWS_PER_STRIP) ? f.longs(TiffFields.ROWS_PER_STRIP)[0] : height;
            if (rows < 1) {
                throw new DemFormatException(tif, "RowsPerStrip (TIFF tag " + TiffFields.ROWS_PER_STRIP + ") is "
                        + rows + "; it must be at least 1");
            }
            blockWidth = width;
            blockHeight = (int) Math.min(height, rows);
        }
        String kind = tiled ? "tile" : "strip";
        long[] offsets = f.longs(tiled ? TiffFields.TILE_OFFSETS : TiffFields.STRIP_OFFSETS);
        long[] counts = f.longs(tiled ? TiffFields.TILE_BYTE_COUNTS : TiffFields.STRIP_BYTE_COUNTS);
        if (offsets.length == 0) {
            throw new DemFormatException(tif, "the TIFF has no " + kind + " offsets");
        }
        long blocks = ((width + (long) blockWidth - 1) / blockWidth) * ((height + (long) blockHeight - 1)
                / blockHeight);
        String image = width + " × " + height + " image in " + (tiled ? "tiles of " + blockWidth + " × "
                + blockHeight : "strips of " + blockHeight + " rows");
        String offsetsTag = tiled ? "TileOffsets (TIFF tag 324)" : "StripOffsets (TIFF tag 273)";
        String countsTag = tiled ? "TileByteCounts (TIFF tag 325)" : "StripByteCounts (TIFF tag 279)";
        if (offsets.length < blocks) {
            throw new DemFormatException(tif, offsetsTag + " has " + values(offsets.length) + ", but a " + image
                    + " has " + blocks + " " + kind + "s");
        }
        if (counts.length > 0 && counts.length < blocks) {
            throw new DemFormatException(tif, countsTag + " has " + values(counts.length) + ", but a " + image
                    + " has " + blocks + " " + kind + "s");
        }
        checkInFile(tif, offsets, counts, fileSize, kind, offsetsTag, countsTag);
        return new TiffBlocks(tiled, blockWidth, blockHeight, offsets, counts);
    }

    /** TileWidth or TileLength: present, from 1 to 2³¹ − 1. */
    private static int dimension(Path tif, TiffFields f, int tag, String name) throws DemFormatException {
        if (!f.has(tag)) {
            throw new DemFormatException(tif, name + " (TIFF tag " + tag + ") is missing; a tiled TIFF needs it");
        }
        long v = f.longs(tag)[0];
        if (v < 1 || v > Integer.MAX_VALUE) {
            throw new DemFormatException(tif, name + " (TIFF tag " + tag + ") is " + v + "; it must be from 1 to "
                    + Integer.MAX_VALUE);
        }
        return (int) v;
    }

    /** Refuses negative offsets or byte counts and blocks reaching past the end of the file. */
    private static void checkInFile(Path tif, long[] offsets, long[] counts, long size, String kind,
                                    String offsetsTag, String countsTag) throws DemFormatException {
        long end = 0;
        for (int i = 0; i < offsets.length; i++) {
            long count = i < counts.length ? counts[i] : 0;
            if (offsets[i] < 0) {
                throw new DemFormatException(tif, offsetsTag + " gives " + kind + " " + i + " the offset "
                        + offsets[i] + "; offsets must lie in the file (0 to " + size + ")");
            }
            if (count < 0) {
                throw new DemFormatException(tif, countsTag + " gives " + kind + " " + i + " " + count
                        + " bytes; byte counts cannot be negative");
            }
            end = Math.max(end, MemoryGuard.saturatedAdd(offsets[i], count));
        }
        if (end > size) {
            throw new DemFormatException(tif, "truncated TIFF: its " + kind + "s reach "
                    + (end == Long.MAX_VALUE ? "past byte " + Long.MAX_VALUE : "byte " + end)
                    + " but the file has " + size + " bytes");
        }
    }

    private static String values(int n) {
        return n + (n == 1 ? " value" : " values");
    }
}

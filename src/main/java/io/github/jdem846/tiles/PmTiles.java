package io.github.jdem846.tiles;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.zip.GZIPOutputStream;

/**
 * The parts of the PMTiles version 3 format this library writes (protomaps/PMTiles, {@code spec/v3/spec.md}): tile
 * IDs on the Hilbert curves of the zoom levels, directories of varint-encoded entries, and the 127-byte header.
 */
final class PmTiles {

    /** Size of the fixed header. */
    static final int HEADER_BYTES = 127;
    /** The header and the compressed root directory must fit in the first 16 KiB. */
    static final int ROOT_LIMIT = 16384 - HEADER_BYTES;
    static final byte COMPRESSION_NONE = 1;
    static final byte COMPRESSION_GZIP = 2;
    static final byte TILE_TYPE_PNG = 2;

    private PmTiles() {
    }

    /**
     * The tile ID: the tiles of all lower zooms, plus the position of (x, y) on zoom z's Hilbert curve (the spec's
     * reference algorithm; 0/0/0 is 0, 1/0/0 is 1, 12/3423/1763 is 19078479).
     */
    static long tileId(int z, int x, int y) {
        long acc = ((1L << (2 * z)) - 1) / 3;
        long tx = x;
        long ty = y;
        for (int a = z - 1; a >= 0; a--) {
            long s = 1L << a;
            long rx = (s & tx) != 0 ? 1 : 0;
            long ry = (s & ty) != 0 ? 1 : 0;
            acc += ((3 * rx) ^ ry) << (2 * a);
            // rotate the quadrant
            if (ry == 0) {
                if (rx == 1) {
                    tx = s - 1 - tx;
                    ty = s - 1 - ty;
                }
                long t = tx;
                tx = ty;
                ty = t;
            }
        }
        return acc;
    }

    /** @return the tile ID of {@code t} */
    static long tileId(WebMercatorTile t) {
        return tileId(t.z(), t.x(), t.y());
    }

    /**
     * One directory entry.
     *
     * @param tileId    first tile ID
     * @param offset    bytes from the start of the tile data (or leaf directory) section
     * @param length    bytes, > 0
     * @param runLength tiles that share the data (0 = a leaf directory)
     */
    record Entry(long tileId, long offset, long length, long runLength) {
    }

    /** The gzip-compressed encoding of a directory (spec 4.2). */
    static byte[] directory(List<Entry> entries) {
        ByteArrayOutputStream raw = new ByteArrayOutputStream();
        varint(raw, entries.size());
        long last = 0;
        for (Entry e : entries) {
            varint(raw, e.tileId() - last);
            last = e.tileId();
        }
        for (Entry e : entries) {
            varint(raw, e.runLength());
        }
        for (Entry e : entries) {
            varint(raw, e.length());
        }
        for (int i = 0; i < entries.size(); i++) {
            Entry e = entries.get(i);
            if (i > 0 && e.offset() == entries.get(i - 1).offset() + entries.get(i - 1).length()) {
                varint(raw, 0);
            } else {
                varint(raw, e.offset() + 1);
            }
        }
        return gzip(raw.toByteArray());
    }

    /**
     * The root directory and the leaf directories of {@code entries}: all in the root when it fits {@link
     * #ROOT_LIMIT}, else leaves of 4096, 8192, … entries until the root of their entries fits.
     *
     * @return {root, leaves}
     */
    static byte[][] directories(List<Entry> entries) {
        byte[] root = directory(entries);
        if (root.length <= ROOT_LIMIT) {
            return new byte[][] {root, new byte[0]};
        }
        for (int leafSize = 4096; ; leafSize *= 2) {
            List<Entry> roots = new ArrayList<>();
            ByteArrayOutputStream leaves = new ByteArrayOutputStream();
            for (int i = 0; i < entries.size(); i += leafSize) {
                byte[] leaf = directory(entries.subList(i, Math.min(entries.size(), i + leafSize)));
                roots.add(new Entry(entries.get(i).tileId(), leaves.size(), leaf.length, 0));
                leaves.writeBytes(leaf);
            }
            root = directory(roots);
            if (root.length <= ROOT_LIMIT) {
                return new byte[][] {root, leaves.toByteArray()};
            }
        }
    }

    /**
     * The header fields, in order (spec 3).
     *
     * @param bounds south, west, north, east and centre latitude/longitude in degrees
     */
    record Header(long rootOffset, long rootLength, long metadataOffset, long metadataLength, long leafOffset,
                  long leafLength, long dataOffset, long dataLength, long addressedTiles, long tileEntries,
                  long tileContents, boolean clustered, int minZoom, int maxZoom, double minLon, double minLat,
                  double maxLon, double maxLat, int centerZoom, double centerLon, double centerLat) {

        byte[] encode() {
            ByteBuffer b = ByteBuffer.allocate(HEADER_BYTES).order(ByteOrder.LITTLE_ENDIAN);
            b.put("PMTiles".getBytes(StandardCharsets.UTF_8));
            b.put((byte) 3);
            b.putLong(rootOffset).putLong(rootLength).putLong(metadataOffset).putLong(metadataLength)
                    .putLong(leafOffset).putLong(leafLength).putLong(dataOffset).putLong(dataLength)
                    .putLong(addressedTiles).putLong(tileEntries).putLong(tileContents);
            b.put((byte) (clustered ? 1 : 0));
            b.put(COMPRESSION_GZIP);   // internal compression: directories and metadata
            b.put(COMPRESSION_NONE);   // PNG tiles are stored as they are
            b.put(TILE_TYPE_PNG);
            b.put((byte) minZoom).put((byte) maxZoom);
            b.putInt(e7(minLon)).putInt(e7(minLat)).putInt(e7(maxLon)).putInt(e7(maxLat));
            b.put((byte) centerZoom);
            b.putInt(e7(centerLon)).putInt(e7(centerLat));
            return b.array();
        }

        private static int e7(double degrees) {
            return (int) Math.round(degrees * 1e7);
        }
    }

    static void varint(ByteArrayOutputStream out, long v) {
        long x = v;
        while ((x & ~0x7FL) != 0) {
            out.write((int) ((x & 0x7F) | 0x80));
            x >>>= 7;
        }
        out.write((int) x);
    }

    static byte[] gzip(byte[] data) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try (GZIPOutputStream z = new GZIPOutputStream(out)) {
            z.write(data);
        } catch (IOException e) {
            throw new UncheckedIOException(e); // not for memory
        }
        return out.toByteArray();
    }
}

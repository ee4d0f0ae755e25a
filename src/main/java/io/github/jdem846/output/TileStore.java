package io.github.jdem846.output;

import java.io.Closeable;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;

/**
 * The compressed tiles of one COG level, kept in a scratch file in the order they are added (row-major), each
 * framed as GDAL's COG layout frames it: a leader of 4 bytes giving the tile's size (unsigned, little-endian),
 * the tile, and a trailer repeating the tile's last 4 bytes. The file is copied as a whole into the COG; the
 * offsets and sizes it records are those of the tiles themselves, without leader and trailer.
 */
final class TileStore implements Closeable {

    /** Bytes around each tile: the leader and the trailer. */
    static final int FRAME_BYTES = 8;

    private final Path file;
    private final FileChannel channel;
    private final long[] offsets;
    private final long[] counts;
    private int next;
    private long size;

    /** A store of {@code tiles} tiles in the new file {@code file}, which {@link #close()} deletes. */
    TileStore(Path file, int tiles) throws IOException {
        this.file = file;
        this.channel = FileChannel.open(file, StandardOpenOption.WRITE, StandardOpenOption.READ,
                StandardOpenOption.TRUNCATE_EXISTING);
        this.offsets = new long[tiles];
        this.counts = new long[tiles];
    }

    /** Adds the next tile (at least 4 bytes, as every zlib stream is). */
    void add(byte[] tile) throws IOException {
        if (next == offsets.length) {
            throw new IllegalStateException("all " + offsets.length + " tiles were added");
        }
        ByteBuffer framed = ByteBuffer.allocate(tile.length + FRAME_BYTES).order(ByteOrder.LITTLE_ENDIAN);
        framed.putInt(tile.length).put(tile).put(tile, tile.length - 4, 4).flip();
        FileChannels.writeFully(channel, framed, size);
        offsets[next] = size + 4;
        counts[next] = tile.length;
        size += tile.length + FRAME_BYTES;
        next++;
    }

    /** @return whether every tile was added */
    boolean isComplete() {
        return next == offsets.length;
    }

    /** @return the bytes of the store, leaders and trailers included */
    long size() {
        return size;
    }

    /** @return the offsets of the tiles once the store is copied to {@code base} */
    long[] offsets(long base) {
        long[] o = new long[offsets.length];
        for (int i = 0; i < o.length; i++) {
            o[i] = base + offsets[i];
        }
        return o;
    }

    /** @return the sizes of the tiles */
    long[] counts() {
        return counts.clone();
    }

    /** Copies the whole store into {@code out} at {@code at}. */
    void copyTo(FileChannel out, long at) throws IOException {
        out.position(at);
        for (long done = 0; done < size; ) {
            long n = channel.transferTo(done, size - done, out);
            if (n <= 0) {
                throw new IOException("could not copy the tiles of " + file);
            }
            done += n;
        }
    }

    /** Closes and deletes the scratch file. */
    @Override
    public void close() throws IOException {
        try {
            channel.close();
        } finally {
            Files.deleteIfExists(file);
        }
    }
}

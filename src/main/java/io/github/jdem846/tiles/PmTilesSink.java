package io.github.jdem846.tiles;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Tiles into one PMTiles v3 archive ({@link PmTiles}). Tiles arrive in any order and are appended to a hidden staging
 * file beside the archive; identical tiles (e.g. flat sea) are stored once. At the commit the archive is written to a
 * second hidden file, clustered (tile data in tile-ID order, runs of identical consecutive tiles as one entry),
 * and renamed over the target. Directories and metadata are gzip-compressed, PNG tiles stored as they are.
 */
final class PmTilesSink implements TileSink {

    private record Blob(long offset, int length) {
    }

    private record Written(long tileId, Blob blob) {
    }

    private final Path target;
    private final Path staging;
    private final FileChannel data;
    private final Map<String, Blob> byContent = new HashMap<>();
    private final List<Written> tiles = new ArrayList<>();
    private long size;
    private Path assembling;

    PmTilesSink(Path target) throws IOException {
        this.target = target;
        checkTarget(target);
        this.staging = StagingDirectory.siblingOf(target);
        this.data = FileChannel.open(staging, StandardOpenOption.CREATE_NEW, StandardOpenOption.READ,
                StandardOpenOption.WRITE);
    }

    /**
     * Fails before any work when {@code target} cannot be written.
     *
     * @throws IOException naming the file and what is wrong
     */
    static void checkTarget(Path target) throws IOException {
        Path parent = StagingDirectory.parentOf(target);
        if (!Files.isDirectory(parent)) {
            throw new IOException("cannot write " + target + ": directory " + parent + " does not exist");
        }
        if (!Files.isWritable(parent)) {
            throw new IOException("cannot write " + target + ": directory " + parent + " is not writable");
        }
        if (Files.isDirectory(target)) {
            throw new IOException("cannot write " + target + ": it is a directory");
        }
    }

    @Override
    public synchronized void write(WebMercatorTile tile, byte[] png) throws IOException {
        String key = digest(png);
        Blob blob = byContent.get(key);
        if (blob == null) {
            blob = new Blob(size, png.length);
            ByteBuffer b = ByteBuffer.wrap(png);
            while (b.hasRemaining()) {
                data.write(b, size + b.position());
            }
            size += png.length;
            byContent.put(key, blob);
        }
        tiles.add(new Written(PmTiles.tileId(tile), blob));
    }

    @Override
    public synchronized void commit(TileSetInfo info) throws IOException {
        if (tiles.isEmpty()) {
            throw new IOException("no tile holds data: nothing to write to " + target);
        }
        List<Written> sorted = new ArrayList<>(tiles);
        sorted.sort(Comparator.comparingLong(Written::tileId));
        // lay the data out in tile-ID order, each distinct blob once, and merge runs of the same blob
        Map<Blob, Long> newOffset = new HashMap<>();
        List<Blob> order = new ArrayList<>();
        List<PmTiles.Entry> entries = new ArrayList<>();
        long next = 0;
        for (Written w : sorted) {
            Long at = newOffset.get(w.blob());
            if (at == null) {
                at = next;
                newOffset.put(w.blob(), at);
                order.add(w.blob());
                next += w.blob().length();
            }
            PmTiles.Entry last = entries.isEmpty() ? null : entries.get(entries.size() - 1);
            if (last != null && last.offset() == at && last.tileId() + last.runLength() == w.tileId()) {
                entries.set(entries.size() - 1, new PmTiles.Entry(last.tileId(), at, last.length(),
                        last.runLength() + 1));
            } else {
                entries.add(new PmTiles.Entry(w.tileId(), at, w.blob().length(), 1));
            }
        }
        byte[][] dirs = PmTiles.directories(entries);
        byte[] metadata = PmTiles.gzip(metadataJson(info).getBytes(StandardCharsets.UTF_8));
        long rootOffset = PmTiles.HEADER_BYTES;
        long metadataOffset = rootOffset + dirs[0].length;
        long leafOffset = metadataOffset + metadata.length;
        long dataOffset = leafOffset + dirs[1].length;
        var b = info.bounds();
        PmTiles.Header header = new PmTiles.Header(rootOffset, dirs[0].length, metadataOffset, metadata.length,
                leafOffset, dirs[1].length, dataOffset, next, sorted.size(), entries.size(), order.size(), true,
                minZoom(sorted), maxZoom(sorted), b.west(), b.south(), b.east(), b.north(), info.zooms().min(),
                (b.west() + b.east()) / 2, (b.south() + b.north()) / 2);
        assembling = StagingDirectory.siblingOf(target);
        try (OutputStream out = Files.newOutputStream(assembling, StandardOpenOption.CREATE_NEW)) {
            out.write(header.encode());
            out.write(dirs[0]);
            out.write(metadata);
            out.write(dirs[1]);
            for (Blob blob : order) {
                ByteBuffer buf = ByteBuffer.allocate(blob.length());
                while (buf.hasRemaining()) {
                    if (data.read(buf, blob.offset() + buf.position()) < 0) {
                        throw new IOException("the staged tile data in " + staging + " ended early");
                    }
                }
                out.write(buf.array());
            }
        }
        StagingDirectory.move(assembling, target, true);
        assembling = null;
    }

    @Override
    public synchronized void close() throws IOException {
        try {
            data.close();
        } finally {
            Files.deleteIfExists(staging);
            if (assembling != null) {
                Files.deleteIfExists(assembling);
            }
        }
    }

    private static int minZoom(List<Written> sorted) {
        return zoomOf(sorted.get(0).tileId());
    }

    private static int maxZoom(List<Written> sorted) {
        return zoomOf(sorted.get(sorted.size() - 1).tileId());
    }

    /** The zoom of a tile ID: the z with (4^z − 1)/3 ≤ id < (4^(z+1) − 1)/3. */
    static int zoomOf(long tileId) {
        int z = 0;
        while (((1L << (2 * (z + 1))) - 1) / 3 <= tileId) {
            z++;
        }
        return z;
    }

    private static String metadataJson(TileSetInfo info) {
        var b = info.bounds();
        return String.format(Locale.ROOT, "{\"name\":\"%s\",\"description\":\"%s\",\"type\":\"baselayer\","
                + "\"format\":\"png\",\"minzoom\":%d,\"maxzoom\":%d,\"bounds\":[%.7f,%.7f,%.7f,%.7f]}",
                jsonText(info.name()), jsonText(info.description()), info.zooms().min(), info.zooms().max(),
                b.west(), b.south(), b.east(), b.north());
    }

    private static String jsonText(String s) {
        StringBuilder out = new StringBuilder();
        for (char c : s.toCharArray()) {
            if (c == '"' || c == '\\') {
                out.append('\\').append(c);
            } else if (c < 0x20) {
                out.append(String.format(Locale.ROOT, "\\u%04x", (int) c));
            } else {
                out.append(c);
            }
        }
        return out.toString();
    }

    private static String digest(byte[] bytes) {
        try {
            byte[] d = MessageDigest.getInstance("SHA-256").digest(bytes);
            StringBuilder s = new StringBuilder(64);
            for (byte x : d) {
                s.append(Character.forDigit((x >> 4) & 15, 16)).append(Character.forDigit(x & 15, 16));
            }
            return s.toString();
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is part of every Java platform", e);
        }
    }
}

package io.github.jdem846.io;

import io.github.jdem846.testing.TinyTiff;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.source.RasterSource;
import io.github.jdem846.raster.Dem;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A TIFF directory whose strip or tile structure is corrupt (as a seeded mutation fuzzer makes them: a flipped
 * type bit turning counts into negative SBYTEs, a zero or negative tile size) is refused by read, inspect and
 * statistics alike with the file's name, the tag and the value; never a NegativeArraySizeException, an
 * ArrayIndexOutOfBoundsException, "Negative position" or "/ by zero".
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class TiffStructureTest {

    @TempDir
    Path tmp;

    private static void assertRefused(Path file, String... parts) {
        for (TiffStructureTest.Read read : new Read[] {DemReader::read, DemReader::inspect, DemReader::statistics}) {
            DemFormatException e = assertThrows(DemFormatException.class, () -> read.apply(file));
            String m = e.getMessage();
            assertTrue(m.startsWith(file + ": "), m);
            for (String part : parts) {
                assertTrue(m.contains(part), "'" + part + "' missing in: " + m);
            }
        }
    }

    @FunctionalInterface
    private interface Read {
        Object apply(Path file) throws IOException;
    }

    /** 32 × 32 int16 cells 0, 1, 2, … row by row. */
    private static byte[] ramp() {
        ByteBuffer b = ByteBuffer.allocate(32 * 32 * 2).order(ByteOrder.LITTLE_ENDIAN);
        for (int i = 0; i < 32 * 32; i++) {
            b.putShort((short) i);
        }
        return b.array();
    }

    @Test
    void tileSizesMustBeAtLeastOne() throws IOException {
        assertRefused(TinyTiff.int16(32, 32).data(new byte[512]).tiled(-16, 16, 4).write(tmp, "neg.tif"),
                "TileWidth (TIFF tag 322) is -16; it must be from 1 to 2147483647");
        assertRefused(TinyTiff.int16(32, 32).data(new byte[512]).tiled(16, 0, 4).write(tmp, "zero.tif"),
                "TileLength (TIFF tag 323) is 0");
        assertRefused(TinyTiff.int16(32, 32).data(new byte[512]).tiled(16, 16, 4).remove(323)
                .write(tmp, "none.tif"), "TileLength (TIFF tag 323) is missing");
    }

    @Test
    void rowsPerStripMustBeAtLeastOne() throws IOException {
        assertRefused(TinyTiff.int16(32, 32).set(278, TinyTiff.LONG, 0).write(tmp, "rps0.tif"),
                "RowsPerStrip (TIFF tag 278) is 0; it must be at least 1");
        assertRefused(TinyTiff.int16(32, 32).set(278, TinyTiff.SLONG, -3).write(tmp, "rpsneg.tif"),
                "RowsPerStrip (TIFF tag 278) is -3");
    }

    @Test
    void rowsPerStripOfTwoToThe32MinusOneIsOneStrip() throws IOException {
        // the TIFF default, written out by some tools: one strip, not a negative int
        Dem expected = DemReader.read(TinyTiff.int16(32, 32).data(ramp()).write(tmp, "one.tif"));
        Path max = TinyTiff.int16(32, 32).data(ramp()).set(278, TinyTiff.LONG, 0xFFFFFFFFL).write(tmp, "max.tif");
        Dem got = DemReader.read(max);
        assertArrayEquals(expected.backingArray(), got.backingArray());
        assertEquals(32 * 32 - 1, got.get(31, 31));
        try (RasterSource s = DemReader.open(max)) {
            assertEquals(32, s.naturalRowBlock());
        }
    }

    @Test
    void stripOffsetsAndByteCountsMustLieInTheFile() throws IOException {
        assertRefused(TinyTiff.int16(32, 32).set(273, TinyTiff.SLONG, -112).write(tmp, "negoff.tif"),
                "StripOffsets (TIFF tag 273) gives strip 0 the offset -112; offsets must lie in the file");
        assertRefused(TinyTiff.int16(32, 32).set(279, TinyTiff.SLONG, -16).write(tmp, "negcount.tif"),
                "StripByteCounts (TIFF tag 279) gives strip 0 -16 bytes; byte counts cannot be negative");
        Path past = TinyTiff.int16(32, 32).set(273, TinyTiff.LONG, 1_000_000).write(tmp, "past.tif");
        assertRefused(past, "truncated TIFF: its strips reach byte 1002048 but the file has");
        assertRefused(TinyTiff.int16(32, 32).set(279, TinyTiff.LONG, 0xFFFFFFF0L).write(tmp, "huge.tif"),
                "truncated TIFF: its strips reach byte 42949");
    }

    @Test
    void offsetsAndCountsMustCoverEveryBlock() throws IOException {
        assertRefused(TinyTiff.int16(32, 32).set(278, TinyTiff.LONG, 16).write(tmp, "few.tif"),
                "StripOffsets (TIFF tag 273) has 1 value, but a 32 × 32 image in strips of 16 rows has 2 strips");
        assertRefused(TinyTiff.int16(32, 32).data(new byte[512]).tiled(16, 16, 4).set(325, TinyTiff.LONG, 512, 512)
                .write(tmp, "fewcounts.tif"), "TileByteCounts (TIFF tag 325) has 2 values, but a 32 × 32 image in"
                + " tiles of 16 × 16 has 4 tiles");
    }

    @Test
    void aTileLargerThanOneJavaArrayIsRefusedWhenRead() throws IOException {
        // 65536 × 65536 int16 = 8 GiB a tile, on a 32 × 32 image: the header reads, the pixels are refused
        Path tif = TinyTiff.int16(32, 32).data(new byte[2048]).tiled(65536, 65536, 1).write(tmp, "bigtile.tif");
        assertEquals(32, DemReader.inspect(tif).width());
        for (Read read : new Read[] {DemReader::read, DemReader::statistics}) {
            DemFormatException e = assertThrows(DemFormatException.class, () -> read.apply(tif));
            // refused by the memory guard, which counts a tile decoded whole (16 GiB: stored and decoded), or,
            // on a heap that large, when the tile is decoded
            assertTrue(e.getMessage().startsWith(tif + ": its tiles hold 8.0 GiB each, more than one Java array")
                    || e.getMessage().startsWith(tif + ": ") && e.getMessage().contains(
                    "16.0 GiB to decode the strips or tiles it covers"), e.getMessage());
        }
    }

    @Test
    void aFirstDirectoryPastTheEndIsRefused() throws IOException {
        Path tif = TinyTiff.int16(32, 32).firstIfd(1_000_000).write(tmp, "noifd.tif");
        assertRefused(tif, "truncated or corrupt");
    }

    @Test
    void directoryChainsThatLoopOrLeaveTheFileEndAfterTheFirstImage() throws IOException {
        // only the first image is read; a corrupt chain after it neither hangs (the class timeout) nor fails
        for (long next : new long[] {FIRST_IFD, 1_000_000, 3}) {
            Path tif = TinyTiff.int16(32, 32).data(ramp()).nextIfd(next).write(tmp, "chain" + next + ".tif");
            assertEquals(32 * 32 - 1, DemReader.read(tif).get(31, 31));
            assertEquals(32 * 32, DemReader.statistics(tif).validCount());
        }
    }

    /** The first image directory of a {@link TinyTiff}: a next pointer to it makes a loop. */
    private static final long FIRST_IFD = 8;

    @Test
    void fieldValuesOutsideTheFileAreNamed() throws IOException {
        byte[] b = TinyTiff.int16(32, 32).set(278, TinyTiff.LONG, 16).set(273, TinyTiff.LONG, TinyTiff.AT_DATA,
                TinyTiff.AT_DATA).set(279, TinyTiff.LONG, 1024, 1024).bytes();
        ByteBuffer bb = ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN);
        for (int i = 0; i < bb.getShort(8); i++) {
            int at = 10 + 12 * i;
            if (bb.getShort(at) == 273) {
                bb.putInt(at + 8, 1_000_000); // the two offsets are read from past the end
            }
        }
        Path tif = tmp.resolve("outside.tif");
        java.nio.file.Files.write(tif, b);
        assertRefused(tif, "the values of TIFF tag 273 lie outside the file (");
    }

    @Test
    void wholeNumberTagsHoldingOtherValuesAreRefused() throws IOException {
        // a type flipped to RATIONAL turns StripOffsets into "a/b" fractions
        byte[] b = TinyTiff.int16(4, 4).bytes();
        ByteBuffer bb = ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN);
        int n = bb.getShort(8);
        for (int i = 0; i < n; i++) {
            int at = 10 + 12 * i;
            if (bb.getShort(at) == 273) {
                bb.putShort(at + 2, (short) 5); // RATIONAL: 8 bytes, so the value is read at the 'offset'
                bb.putInt(at + 8, 0);
            }
        }
        Path tif = tmp.resolve("rational.tif");
        java.nio.file.Files.write(tif, b);
        for (Read read : new Read[] {DemReader::read, DemReader::inspect, DemReader::statistics}) {
            DemFormatException e = assertThrows(DemFormatException.class, () -> read.apply(tif));
            assertTrue(e.getMessage().startsWith(tif + ": ") && e.getMessage().contains("TIFF tag 273 holds '")
                    && e.getMessage().endsWith("', not a whole number"), e.getMessage());
        }
    }
}

package io.github.jdem846.io;

import io.github.jdem846.testing.TinyTiff;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.source.MemoryGuard;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Headers declaring absurd sizes are refused before anything is allocated, with a message naming the file and
 * giving true figures: sizes are computed without overflow ("16.0 EiB", not "-17179869180 bytes").
 */
class HugeSizeTest {

    @TempDir
    Path tmp;

    private static void assertNoNegativeNumber(String message) {
        assertFalse(message.matches("(?s).*[^\\w.]-\\d.*"), "a negative size in: " + message);
    }

    @Test
    void sizesAreFormattedWithoutOverflow() {
        assertEquals("more than 8 EiB", MemoryGuard.human(Long.MAX_VALUE));
        assertEquals("16.0 EiB", MemoryGuard.human(Math.pow(2, 64)));
        assertEquals("37.3 GiB", MemoryGuard.human(40_000_000_000L));
        assertEquals("1000 bytes", MemoryGuard.human(1000L));
        assertEquals(Long.MAX_VALUE, MemoryGuard.saturatedMultiply(1L << 40, 1L << 30));
        assertEquals(Long.MAX_VALUE, MemoryGuard.saturatedMultiply(Integer.MAX_VALUE, Long.MAX_VALUE / 2));
        assertEquals(6L << 40, MemoryGuard.saturatedMultiply(3L << 20, 2L << 20));
        assertEquals(Long.MAX_VALUE, MemoryGuard.saturatedAdd(Long.MAX_VALUE - 1, 2));
    }

    @Test
    void theLargestGridIsRefusedWithItsTrueSize() {
        // 2147483647² × 4 bytes is 2⁶⁴ − 2³⁴ + 4: as a long it printed "-17179869180 bytes"
        DemFormatException e = assertThrows(DemFormatException.class, () -> MemoryGuard.requireFits(
                Path.of("big.flt"), Integer.MAX_VALUE, Integer.MAX_VALUE, 0, "read a window"));
        String m = e.getMessage();
        assertTrue(m.startsWith("big.flt: ") && m.contains("16.0 EiB"), m);
        assertNoNegativeNumber(m);
    }

    @Test
    void aBillionSquareTiffIsRefusedByReadAndStatisticsBeforeAllocating() throws IOException {
        Path tif = TinyTiff.int16(1_000_000_000L, 1_000_000_000L).write(tmp, "billion.tif");
        assertEquals(1_000_000_000, DemReader.inspect(tif).width(), "the header alone reads");

        DemFormatException stats = assertThrows(DemFormatException.class, () -> DemReader.statistics(tif));
        String m = stats.getMessage();
        assertTrue(m.startsWith(tif + ": reading it takes 1000000000 × 1000000000 cells at a time"), m);
        assertTrue(m.contains("3.5 EiB as float32, more than one Java array can hold"), m);

        DemFormatException read = assertThrows(DemFormatException.class, () -> DemReader.read(tif));
        assertTrue(read.getMessage().startsWith(tif + ": a 1000000000 × 1000000000 grid has"), read.getMessage());
        assertTrue(read.getMessage().contains("it would need 3.5 EiB"), read.getMessage());

        // decimated to 1000 × 1000, the output would fit, but not the band of a strip of 10⁹ rows
        DemFormatException decimated = assertThrows(DemFormatException.class,
                () -> DemReader.read(tif, ReadRequest.decimated(1_000_000)));
        assertTrue(decimated.getMessage().startsWith(tif + ": reading it takes 1000000000 × "),
                decimated.getMessage());
    }

    @Test
    void aStripWiderThanTheHeapIsRefusedByStatistics() throws IOException {
        // one row of 10⁹ cells fits in an array of floats but not in a 2 GiB heap, and is declared as one strip
        long max = Runtime.getRuntime().maxMemory();
        long width = Math.min(2_000_000_000L, max / 4 + 1);
        Path tif = TinyTiff.int16(width, 1).write(tmp, "wide.tif");
        DemFormatException e = assertThrows(DemFormatException.class, () -> DemReader.statistics(tif));
        assertTrue(e.getMessage().startsWith(tif + ": reading it takes " + width + " × 1 cells at a time"),
                e.getMessage());
    }

    @Test
    void rowsLongerThanOneReadAreReadInPieces() throws IOException {
        // 1 100 000 float32 columns: 4.4 MB a row, more than the 4 MiB read at once
        int cols = 1_100_000;
        java.nio.ByteBuffer b = java.nio.ByteBuffer.allocate(cols * 2 * 4).order(java.nio.ByteOrder.LITTLE_ENDIAN);
        for (int i = 0; i < cols * 2; i++) {
            b.putFloat(i % 1000 + (i >= cols ? 0.5f : 0));
        }
        Path flt = tmp.resolve("long.flt");
        Files.write(flt, b.array());
        Files.writeString(tmp.resolve("long.hdr"), "ncols " + cols + "\nnrows 2\nxllcorner 0\nyllcorner 0\n"
                + "cellsize 1\nbyteorder LSBFIRST\n");
        io.github.jdem846.raster.Dem dem = DemReader.read(flt);
        for (int c : new int[] {0, 999, 1_048_575, 1_048_576, 1_048_577, cols - 1}) {
            assertEquals(c % 1000, dem.get(c, 0), "row 0, column " + c);
            assertEquals(c % 1000 + 0.5f, dem.get(c, 1), "row 1, column " + c);
        }
        io.github.jdem846.raster.Dem window = DemReader.read(flt,
                ReadRequest.of(Window.cells(7, 1, cols - 8, 1)));
        assertEquals((1_048_583 % 1000) + 0.5f, window.get(1_048_576, 0));
        assertEquals(((cols - 2) % 1000) + 0.5f, window.get(cols - 9, 0));
    }

    @Test
    void aGridFloatHeaderOfTwoBillionSquareGivesTheExactExpectedSize() throws IOException {
        Path flt = tmp.resolve("big.flt");
        Files.write(flt, new byte[24]);
        Files.writeString(tmp.resolve("big.hdr"), "ncols 2000000000\nnrows 2000000000\nxllcorner 0\nyllcorner 0\n"
                + "cellsize 1\nbyteorder LSBFIRST\n");
        DemFormatException e = assertThrows(DemFormatException.class, () -> DemReader.inspect(flt));
        String m = e.getMessage();
        // as a long it printed "-2446744073709551616 bytes"
        assertTrue(m.contains("2000000000 × 2000000000 × 4 = 16000000000000000000 bytes"), m);
        assertNoNegativeNumber(m);
    }

    @Test
    void aBilHeaderWhoseRowsPassTheLongRangeIsRefused() throws IOException {
        Path bil = tmp.resolve("big.bil");
        Files.write(bil, new byte[12]);
        Files.writeString(tmp.resolve("big.hdr"), "ncols 3\nnrows 2000000000\nnbits 16\ntotalrowbytes"
                + " 9000000000000000000\nbyteorder I\n");
        DemFormatException e = assertThrows(DemFormatException.class, () -> DemReader.read(bil));
        String m = e.getMessage();
        assertTrue(m.startsWith(bil + ": is 12 bytes but the header needs at least"
                + " 17999999991000000000000000006"), m);
        assertNoNegativeNumber(m);

        Files.writeString(tmp.resolve("big.hdr"), "ncols 3\nnrows 2\nnbits 16\nnbands 4\nbandrowbytes"
                + " 4000000000000000000\nbyteorder I\n");
        e = assertThrows(DemFormatException.class, () -> DemReader.read(bil));
        assertTrue(e.getMessage().contains("nbands 4 × bandrowbytes 4000000000000000000 makes rows of more than"
                + " 8 EiB"), e.getMessage());
    }
}

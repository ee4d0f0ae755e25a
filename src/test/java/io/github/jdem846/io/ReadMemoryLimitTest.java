package io.github.jdem846.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.source.RasterSource;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.testing.SingleStripTiff;
import java.io.IOException;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@link ReadRequest#memoryLimit()} and the strips decoded whole: a small window of a one-strip TIFF costs the
 * whole strip, and the memory guard counts it before anything is allocated.
 */
class ReadMemoryLimitTest {

    @TempDir
    Path tmp;

    @Test
    void aSmallWindowOfOneHugeStripCountsTheStrip() throws IOException {
        Path tif = SingleStripTiff.write(tmp.resolve("strip.tif"), 2000);   // 8 MB decoded
        ReadRequest corner = ReadRequest.of(Window.cells(0, 0, 10, 10));
        Dem dem = DemReader.read(tif, corner.withMemoryLimit(64L << 20));
        assertEquals(10, dem.width());
        DemFormatException e = assertThrows(DemFormatException.class,
                () -> DemReader.read(tif, corner.withMemoryLimit(1L << 20)));
        assertTrue(e.getMessage().startsWith(tif.toString()), e.getMessage());
        assertTrue(e.getMessage().contains("to decode the strips or tiles it covers"), e.getMessage());
        assertTrue(e.getMessage().contains("limit of 1.0 MiB"), e.getMessage());
    }

    @Test
    void blockBytesOfATiledFileAreOneTile() throws IOException {
        Path tiled = Path.of("testdata/variants/bigtujunga_crop600x400_v04_int16_deflate_pred2_tile256.tif");
        try (RasterSource source = DemReader.open(tiled)) {
            assertEquals(2L * 256 * 256 * 2, source.blockBytes());
        }
        Path strip = SingleStripTiff.write(tmp.resolve("strip.tif"), 300);
        try (RasterSource source = DemReader.open(strip)) {
            assertEquals(2L * 300 * 300 * 2, source.blockBytes());
        }
    }

    @Test
    void aLimitBelowTheGridItselfIsRefusedAndAnAmpleOneIsNot() throws IOException {
        Path tif = Path.of("testdata/dem/maungawhau-volcano_10m_nztm-approx.tif");
        DemInfo info = DemReader.inspect(tif);
        long grid = 4L * info.width() * info.height();
        assertThrows(DemFormatException.class, () -> DemReader.read(tif, ReadRequest.FULL.withMemoryLimit(grid - 1)));
        assertEquals(DemReader.read(tif).width(),
                DemReader.read(tif, ReadRequest.FULL.withMemoryLimit(64L << 20)).width());
        assertThrows(IllegalArgumentException.class, () -> ReadRequest.FULL.withMemoryLimit(-1));
    }
}

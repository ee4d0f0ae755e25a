package io.github.jdem846.io.geotiff;

import static io.github.jdem846.io.DemAssertions.assertSameValues;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import com.twelvemonkeys.imageio.plugins.tiff.TIFFImageReaderSpi;
import io.github.jdem846.io.DemFormatException;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.io.ReadRequest;
import io.github.jdem846.io.Window;
import io.github.jdem846.raster.Dem;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageReader;
import javax.imageio.stream.FileImageInputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A window of a TIFF decodes only the strips or tiles under it: a copy whose other strips or tiles are destroyed
 * still gives the right window, while the full read of the same copy fails.
 */
class TiffSubsetTest {

    @TempDir
    Path tmp;

    /** Copies {@code tif} with every strip/tile except those listed overwritten by garbage. */
    private Path damagedCopy(Path tif, int... keep) throws IOException {
        TiffFields f;
        ImageReader r = new TIFFImageReaderSpi().createReaderInstance();
        try (FileImageInputStream in = new FileImageInputStream(tif.toFile())) {
            r.setInput(in, true, false);
            f = TiffFields.of(r.getImageMetadata(0));
        } finally {
            r.dispose();
        }
        boolean tiled = f.has(TiffFields.TILE_OFFSETS);
        long[] offsets = f.longs(tiled ? TiffFields.TILE_OFFSETS : TiffFields.STRIP_OFFSETS);
        long[] counts = f.longs(tiled ? TiffFields.TILE_BYTE_COUNTS : TiffFields.STRIP_BYTE_COUNTS);
        byte[] bytes = Files.readAllBytes(tif);
        for (int i = 0; i < offsets.length; i++) {
            final int index = i;
            if (java.util.Arrays.stream(keep).anyMatch(k -> k == index)) {
                continue;
            }
            for (long b = offsets[i]; b < offsets[i] + counts[i]; b++) {
                bytes[(int) b] = (byte) (b * 7 + 3);
            }
        }
        Path copy = tmp.resolve("damaged-" + tif.getFileName());
        Files.write(copy, bytes);
        return copy;
    }

    @Test
    void tiledWindowInsideOneTile() throws IOException {
        Path v04 = Path.of("testdata/variants/bigtujunga_crop600x400_v04_int16_deflate_pred2_tile256.tif");
        Dem full = DemReader.read(v04);
        // 600×400 in 256² tiles: 3 across, 2 down. Keep only tile 4 (second row, middle column).
        Path damaged = damagedCopy(v04, 4);
        Window inTile4 = Window.cells(256 + 10, 256 + 5, 200, 130);
        assertSameValues(full.crop(266, 261, 200, 130), DemReader.read(damaged, ReadRequest.of(inTile4)),
                "window inside the kept tile");
        assertThrows(DemFormatException.class, () -> DemReader.read(damaged), "the other tiles are garbage");
    }

    @Test
    void stripedWindowReadsOnlyItsStrips() throws IOException {
        Path v02 = Path.of("testdata/variants/bigtujunga_crop600x400_v02_int16_lzw_pred2_strip16.tif");
        Dem full = DemReader.read(v02);
        // Strips of 16 rows: keep strips 6 and 7 (rows 96–127).
        Path damaged = damagedCopy(v02, 6, 7);
        Dem window = DemReader.read(damaged, ReadRequest.of(Window.cells(33, 100, 500, 25)));
        assertSameValues(full.crop(33, 100, 500, 25), window, "rows 100–124 of strips 6 and 7");
        assertEquals(500, window.width());
    }
}

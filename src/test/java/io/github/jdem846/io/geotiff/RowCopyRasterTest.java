package io.github.jdem846.io.geotiff;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.awt.Point;
import java.awt.image.DataBuffer;
import java.awt.image.PixelInterleavedSampleModel;
import java.awt.image.Raster;
import java.awt.image.WritableRaster;
import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@link RowCopyRaster#setDataElements(int, int, Raster)} leaves the same cells as the JDK's own raster of the same
 * layout, for every data type, for sources that are children (offset, translated, clipped) of larger rasters, for
 * sources it cannot copy row by row (every other cell of a two-band raster), and fails where the JDK fails.
 */
class RowCopyRasterTest {

    private static final int W = 37;
    private static final int H = 23;

    @ParameterizedTest
    @ValueSource(ints = {DataBuffer.TYPE_BYTE, DataBuffer.TYPE_USHORT, DataBuffer.TYPE_SHORT, DataBuffer.TYPE_INT,
        DataBuffer.TYPE_FLOAT, DataBuffer.TYPE_DOUBLE})
    void leavesTheCellsOfTheJdkRaster(int dataType) {
        Random random = new Random(dataType);
        RowCopyRaster fast = RowCopyRaster.create(dataType, W, H);
        WritableRaster jdk = Raster.createWritableRaster(
                new PixelInterleavedSampleModel(dataType, W, H, 1, W, new int[] {0}), new Point(0, 0));
        for (int k = 0; k < 200; k++) {
            int bands = random.nextInt(4) == 0 ? 2 : 1;
            int pw = 1 + random.nextInt(2 * W);
            int ph = 1 + random.nextInt(H);
            WritableRaster parent = Raster.createWritableRaster(new PixelInterleavedSampleModel(dataType, pw, ph,
                    bands, pw * bands + random.nextInt(3) * bands, bands == 1 ? new int[] {0} : new int[] {1, 0}),
                    new Point(random.nextInt(9) - 4, random.nextInt(9) - 4));
            for (int y = 0; y < ph; y++) {
                for (int x = 0; x < pw; x++) {
                    parent.setSample(parent.getMinX() + x, parent.getMinY() + y, bands - 1,
                            random.nextInt(1 << 16) - (1 << 15));
                }
            }
            int cx = random.nextInt(pw);
            int cy = random.nextInt(ph);
            int cw = 1 + random.nextInt(pw - cx);
            int ch = 1 + random.nextInt(ph - cy);
            Raster source = parent.createChild(parent.getMinX() + cx, parent.getMinY() + cy, cw, ch,
                    random.nextInt(5) - 2, random.nextInt(5) - 2, new int[] {bands - 1});
            int x = random.nextInt(W + 4) - 2 - source.getMinX();
            int y = random.nextInt(H + 4) - 2 - source.getMinY();
            boolean inside = x + source.getMinX() >= 0 && y + source.getMinY() >= 0
                    && x + source.getMinX() + cw <= W && y + source.getMinY() + ch <= H;
            if (inside) {
                jdk.setDataElements(x, y, source);
                fast.setDataElements(x, y, source);
            } else {
                assertThrows(ArrayIndexOutOfBoundsException.class, () -> jdk.setDataElements(x, y, source));
                assertThrows(ArrayIndexOutOfBoundsException.class, () -> fast.setDataElements(x, y, source));
            }
        }
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                assertEquals(jdk.getSampleDouble(x, y, 0), fast.getSampleDouble(x, y, 0), "cell " + x + ", " + y);
            }
        }
    }
}

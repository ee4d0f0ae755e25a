package io.github.jdem846.io.geotiff;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.twelvemonkeys.imageio.plugins.tiff.TIFFImageReaderSpi;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.io.SampleType;
import io.github.jdem846.io.source.RasterSource;
import java.awt.image.DataBuffer;
import java.awt.image.Raster;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import javax.imageio.ImageReader;
import javax.imageio.stream.FileImageInputStream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Every GeoTIFF of testdata decodes, through {@link GeoTiffSource} (strip/tile subsets, {@link DecodeTarget}, the
 * array copy), to exactly the bits of a plain decode: TwelveMonkeys' {@code readRaster} of the whole original
 * file, each cell taken with the JDK's own sample getters and the sample type's reading of ints and bytes. Whole
 * files and windows whose edges cut strips and tiles.
 */
class TiffReferenceDecodeTest {

    /**
     * The readable GeoTIFFs of testdata, the bundled sample included (the others must be refused). Sparse files are
     * left out: the plain decode fails on their missing blocks (OtherFormatsTest checks them against the values
     * they were made from).
     */
    static List<Path> tiffs() throws IOException {
        List<Path> files = new ArrayList<>();
        for (String dir : List.of("testdata/dem", "testdata/variants", "testdata/formats",
                "src/cli/resources/io/github/jdem846/sample")) {
            try (Stream<Path> s = Files.list(Path.of(dir))) {
                s.filter(p -> p.toString().endsWith(".tif"))
                        .filter(p -> !p.getFileName().toString().matches(".*_(zstd|cint16|rotated)\\.tif"))
                        .filter(p -> !p.getFileName().toString().contains("_sparse_"))
                        .sorted().forEach(files::add);
            }
        }
        return files;
    }

    @ParameterizedTest
    @MethodSource("tiffs")
    void decodesToTheBitsOfAPlainWholeFileDecode(Path tif) throws IOException {
        float[] reference = plainDecode(tif);
        try (RasterSource source = GeoTiffSource.open(tif)) {
            int w = source.info().width();
            int h = source.info().height();
            assertEquals(reference.length, (long) w * h, tif + ": cells");
            int[][] windows = {{0, 0, w, h}, {1, 3, w - 2, h - 5}, {w / 3, h / 4, w / 2, h / 3 + 1},
                {w - 1, h - 17, 1, 17}};
            for (int[] win : windows) {
                float[] got = new float[win[2] * win[3]];
                source.readRows(win[0], win[1], win[2], win[3], got);
                for (int r = 0; r < win[3]; r++) {
                    for (int c = 0; c < win[2]; c++) {
                        float e = reference[(win[1] + r) * w + win[0] + c];
                        float g = got[r * win[2] + c];
                        if (Float.floatToRawIntBits(e) != Float.floatToRawIntBits(g)) {
                            throw new AssertionError(tif + " window " + java.util.Arrays.toString(win) + " col "
                                    + (win[0] + c) + " row " + (win[1] + r) + ": expected " + e + ", got " + g);
                        }
                    }
                }
            }
        }
    }

    @ParameterizedTest
    @MethodSource("tiffs")
    void oneBandTypesAreDecodedIntoARowCopyTarget(Path tif) throws IOException {
        ImageReader r = new TIFFImageReaderSpi().createReaderInstance();
        try (FileImageInputStream in = new FileImageInputStream(tif.toFile())) {
            r.setInput(in, true, false);
            boolean oneBand = r.getRawImageType(0).getNumBands() == 1;
            DecodeTarget target = DecodeTarget.forRawType(r.getRawImageType(0), 3, 2);
            assertEquals(oneBand, target != null, tif + ": a target exactly for one-band types");
            if (target != null) {
                assertTrue(target.getData() == target.getRaster(), "getData gives the raster itself");
            }
        } finally {
            r.dispose();
        }
    }

    /** Band 1 of the whole image, each cell as the JDK's getters give it, ints and bytes read by sample type. */
    private static float[] plainDecode(Path tif) throws IOException {
        SampleType type = DemReader.inspect(tif).dataType();
        ImageReader r = new TIFFImageReaderSpi().createReaderInstance();
        Raster raster;
        try (FileImageInputStream in = new FileImageInputStream(tif.toFile())) {
            r.setInput(in, true, false);
            raster = r.readRaster(0, null);
        } finally {
            r.dispose();
        }
        int w = raster.getWidth();
        int h = raster.getHeight();
        int dataType = raster.getDataBuffer().getDataType();
        float[] out = new float[w * h];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int px = raster.getMinX() + x;
                int py = raster.getMinY() + y;
                float v;
                if (dataType == DataBuffer.TYPE_BYTE || dataType == DataBuffer.TYPE_INT) {
                    int i = raster.getSample(px, py, 0);
                    v = type == SampleType.INT8 ? (byte) i : type == SampleType.UINT32 ? i & 0xFFFFFFFFL : i;
                } else {
                    v = raster.getSampleFloat(px, py, 0);
                }
                out[y * w + x] = v;
            }
        }
        return out;
    }
}

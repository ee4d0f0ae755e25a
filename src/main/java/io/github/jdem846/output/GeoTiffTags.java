package io.github.jdem846.output;

import io.github.jdem846.internal.GeoKeys;
import io.github.jdem846.output.TiffDirectory.Field;
import java.util.Arrays;

/**
 * The tags of the GeoTIFFs written here, shared by the stripped and the tiled (COG) layouts: the baseline fields
 * of the samples (Deflate compression 8, chunky, 8-bit gray BlackIsZero, 8-bit RGB with unassociated alpha or float32
 * gray; the horizontal differencing predictor 2 for 8-bit samples), GDAL_NODATA (42113), and for the full-resolution
 * image the Software tag and the georeferencing: ModelPixelScale (33550), ModelTiepoint (33922) and the GeoKeys
 * (34735–34737, {@link GeoKeyWriter}).
 */
final class GeoTiffTags {

    static final int TAG_GDAL_NODATA = 42113;

    private GeoTiffTags() {
    }

    /** @return whether samples of {@code bitsPerSample} bits are stored with the horizontal predictor */
    static boolean predictor(int bitsPerSample) {
        return bitsPerSample == 8;
    }

    /**
     * The fields describing the samples of a {@code width × height} image (no strips or tiles, no
     * georeferencing).
     *
     * @param noData the GDAL_NODATA value, or {@code null} for none
     */
    static TiffDirectory samples(int width, int height, int samplesPerPixel, int bitsPerSample, Double noData) {
        TiffDirectory d = new TiffDirectory();
        boolean rgba = samplesPerPixel == 4;
        d.put(256, Field.longs(width));                                   // ImageWidth
        d.put(257, Field.longs(height));                                  // ImageLength
        int[] bits = new int[samplesPerPixel];
        Arrays.fill(bits, bitsPerSample);
        d.put(258, Field.shorts(bits));                                   // BitsPerSample
        d.put(259, Field.shorts(8));                                      // Compression: Deflate
        d.put(262, Field.shorts(rgba ? 2 : 1));                           // Photometric: RGB or BlackIsZero
        d.put(277, Field.shorts(samplesPerPixel));                        // SamplesPerPixel
        d.put(284, Field.shorts(1));                                      // PlanarConfiguration: chunky
        if (predictor(bitsPerSample)) {
            d.put(317, Field.shorts(2));                                  // Predictor: horizontal differencing
        }
        if (rgba) {
            d.put(338, Field.shorts(2));                                  // ExtraSamples: unassociated alpha
        }
        int[] format = new int[samplesPerPixel];
        Arrays.fill(format, bitsPerSample == 32 ? 3 : 1);
        d.put(339, Field.shorts(format));                                 // SampleFormat: IEEE float or uint
        if (noData != null) {
            d.put(TAG_GDAL_NODATA, Field.ascii(noDataText(noData)));
        }
        return d;
    }

    /** Adds the Software tag and, when {@code geo} is given, the georeferencing of a {@code width × height} image. */
    static void describe(TiffDirectory d, GeoReference geo, int width, int height) {
        d.put(305, Field.ascii("jdem846"));                               // Software
        if (geo == null) {
            return;
        }
        d.put(33550, Field.doubles(geo.pixelWidth(width), geo.pixelHeight(height), 0)); // ModelPixelScale
        // PixelIsArea: raster point (0, 0) is the outer north-west corner of the first pixel.
        d.put(33922, Field.doubles(0, 0, 0, geo.westX(), geo.northY(), 0));          // ModelTiepoint
        GeoKeyWriter keys = GeoKeyWriter.of(geo.crs());
        int[] dir = new int[keys.directory().length];
        for (int i = 0; i < dir.length; i++) {
            dir[i] = keys.directory()[i];
        }
        d.put(GeoKeys.TAG_GEO_KEY_DIRECTORY, Field.shorts(dir));
        if (keys.doubleParams().length > 0) {
            d.put(GeoKeys.TAG_GEO_DOUBLE_PARAMS, Field.doubles(keys.doubleParams()));
        }
        if (!keys.asciiParams().isEmpty()) {
            d.put(GeoKeys.TAG_GEO_ASCII_PARAMS, Field.ascii(keys.asciiParams()));
        }
    }

    /** GDAL_NODATA text: an integer without decimals, NaN as "nan", else the shortest float32 decimal. */
    static String noDataText(double value) {
        if (Double.isNaN(value)) {
            return "nan";
        }
        if (value == Math.rint(value) && Math.abs(value) < 1e15) {
            return Long.toString((long) value);
        }
        return Float.toString((float) value);
    }
}

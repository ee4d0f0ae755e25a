package io.github.jdem846.output;

import com.twelvemonkeys.imageio.metadata.Directory;
import com.twelvemonkeys.imageio.metadata.Entry;
import com.twelvemonkeys.imageio.metadata.tiff.TIFFReader;
import com.twelvemonkeys.imageio.plugins.tiff.TIFFImageReaderSpi;
import io.github.jdem846.internal.GeoKeys;
import java.awt.image.BufferedImage;
import java.awt.image.Raster;
import java.io.IOException;
import java.lang.reflect.Array;
import java.nio.file.Path;
import javax.imageio.ImageReader;
import javax.imageio.stream.FileImageInputStream;
import javax.imageio.stream.ImageInputStream;

/**
 * Reads TIFFs back with TwelveMonkeys (independent of the JDK plug-in that writes them): the tags of the first IFD
 * as numbers or text, and the pixels.
 */
final class TiffTags {

    private final Directory ifd;

    private TiffTags(Directory ifd) {
        this.ifd = ifd;
    }

    static TiffTags read(Path file) throws IOException {
        try (ImageInputStream in = new FileImageInputStream(file.toFile())) {
            return new TiffTags(new TIFFReader().read(in));
        }
    }

    boolean has(int tag) {
        return ifd.getEntryById(tag) != null;
    }

    /** The values of a numeric tag (any TIFF integer or floating type, one value or many). */
    double[] numbers(int tag) {
        Entry e = ifd.getEntryById(tag);
        if (e == null) {
            throw new AssertionError("tag " + tag + " missing");
        }
        Object v = e.getValue();
        if (!v.getClass().isArray()) {
            return new double[]{((Number) v).doubleValue()};
        }
        double[] d = new double[Array.getLength(v)];
        for (int i = 0; i < d.length; i++) {
            d[i] = ((Number) Array.get(v, i)).doubleValue();
        }
        return d;
    }

    double number(int tag) {
        double[] d = numbers(tag);
        if (d.length != 1) {
            throw new AssertionError("tag " + tag + " has " + d.length + " values");
        }
        return d[0];
    }

    String text(int tag) {
        Entry e = ifd.getEntryById(tag);
        if (e == null) {
            throw new AssertionError("tag " + tag + " missing");
        }
        return e.getValue().toString();
    }

    /** The value of GeoKey {@code key} stored in the directory itself (location 0). */
    int geoKey(int key) {
        double[] d = numbers(GeoKeys.TAG_GEO_KEY_DIRECTORY);
        for (int k = 0; k < d[3]; k++) {
            int at = 4 + 4 * k;
            if (d[at] == key) {
                if (d[at + 1] != 0) {
                    throw new AssertionError("key " + key + " is stored in tag " + (int) d[at + 1]);
                }
                return (int) d[at + 3];
            }
        }
        throw new AssertionError("GeoKey " + key + " missing");
    }

    /** The image as TwelveMonkeys decodes it (for RGBA, compared through {@code getRGB}). */
    static BufferedImage image(Path file) throws IOException {
        ImageReader reader = new TIFFImageReaderSpi().createReaderInstance(null);
        try (ImageInputStream in = new FileImageInputStream(file.toFile())) {
            reader.setInput(in);
            return reader.read(0);
        } finally {
            reader.dispose();
        }
    }

    /**
     * The stored samples. {@code readRaster}, not {@code read}: TwelveMonkeys 3.15.0's {@code read(0)} clamps
     * float32 gray samples to 0..1 on the way into a BufferedImage.
     */
    static Raster raster(Path file) throws IOException {
        ImageReader reader = new TIFFImageReaderSpi().createReaderInstance(null);
        try (ImageInputStream in = new FileImageInputStream(file.toFile())) {
            reader.setInput(in);
            return reader.readRaster(0, null);
        } finally {
            reader.dispose();
        }
    }
}

package io.github.jdem846.output;

import com.pngencoder.PngEncoder;
import io.github.jdem846.testing.SyntheticDems;
import io.github.jdem846.testing.SyntheticDems.ShadedRelief;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.stream.ImageOutputStream;

/**
 * Measures PNG encoders on a realistic rendered product (not a test; run by hand, see docs/performance.md):
 * ImageIO's PNG writer against {@link PngEncoder} at several compression levels, with and without its
 * multi-threaded deflate and its predictor (PNG filter) encoding, and against our {@link PngWriter} (the one
 * {@link ImageOutput} uses) on one thread (1T) and in parallel (MT). Each configuration is run once to warm up and
 * then {@code runs} times; the best wall time is reported with the file size. Every output is decoded with ImageIO
 * once and compared pixel by pixel with the source, so a fast but wrong encoder cannot win.
 *
 * <p>Arguments: {@code [size=4000] [runs=3] [outDir=target/png-bench] [configRegex=.*]}.
 */
public final class PngEncodingComparison {

    private interface Encoder {
        void encode(BufferedImage image, Path file) throws IOException;
    }

    private record Config(String name, Encoder encoder) {
    }

    public static void main(String[] args) throws IOException {
        int size = args.length > 0 ? Integer.parseInt(args[0]) : 4000;
        int runs = args.length > 1 ? Integer.parseInt(args[1]) : 3;
        Path dir = Path.of(args.length > 2 ? args[2] : "target/png-bench");
        String only = args.length > 3 ? args[3] : ".*";
        Files.createDirectories(dir);
        ShadedRelief relief = SyntheticDems.shadedRelief(size, size, 846);
        BufferedImage rgba = Rasters.argbImage(relief.argb(), size, size);
        BufferedImage gray = Rasters.grayImage(relief.gray(), size, size);
        System.out.printf(Locale.ROOT, "nproc=%d, java %s, pngencoder default level %d%n",
                Runtime.getRuntime().availableProcessors(), System.getProperty("java.version"),
                PngEncoder.DEFAULT_COMPRESSION_LEVEL);
        for (BufferedImage image : List.of(rgba, gray)) {
            String kind = image == rgba ? "RGBA" : "gray";
            for (Config config : configs()) {
                if (!config.name().matches(only)) {
                    continue;
                }
                Path file = dir.resolve(kind + "-" + config.name().replaceAll("[^A-Za-z0-9]+", "_") + ".png");
                config.encoder().encode(image, file); // warm-up
                verify(image, file, config.name());
                long best = Long.MAX_VALUE;
                for (int i = 0; i < runs; i++) {
                    long t0 = System.nanoTime();
                    config.encoder().encode(image, file);
                    best = Math.min(best, System.nanoTime() - t0);
                }
                System.out.printf(Locale.ROOT, "| %s %d×%d | %-34s | %7.0f ms | %6.2f MB |%n", kind, size, size,
                        config.name(), best / 1e6, Files.size(file) / 1e6);
            }
        }
    }

    private static List<Config> configs() {
        List<Config> list = new ArrayList<>();
        list.add(new Config("ImageIO default", (img, f) -> imageIo(img, f, Float.NaN)));
        list.add(new Config("ImageIO quality 0.0 (deflate 9)", (img, f) -> imageIo(img, f, 0f)));
        list.add(new Config("ImageIO quality 0.75 (deflate 2)", (img, f) -> imageIo(img, f, 0.75f)));
        for (int level : new int[]{1, 6}) {
            for (boolean mt : new boolean[]{false, true}) {
                String name = "PngWriter L" + level + (mt ? " MT" : " 1T");
                list.add(new Config(name, (img, f) -> PngWriter.write(img, f, level, mt)));
            }
        }
        for (boolean predictor : new boolean[]{false, true}) {
            for (int level : new int[]{1, 3, 6, 9}) {
                for (boolean mt : new boolean[]{false, true}) {
                    String name = "PngEncoder L" + level + (mt ? " MT" : " 1T") + (predictor ? " predictor" : "");
                    list.add(new Config(name, (img, f) -> pngEncoder(img, f, level, mt, predictor)));
                }
            }
        }
        return list;
    }

    private static void imageIo(BufferedImage image, Path file, float quality) throws IOException {
        ImageWriter writer = ImageIO.getImageWritersByFormatName("png").next();
        try (ImageOutputStream out = ImageIO.createImageOutputStream(Files.newOutputStream(file))) {
            ImageWriteParam param = writer.getDefaultWriteParam();
            if (!Float.isNaN(quality)) {
                param.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
                param.setCompressionQuality(quality);
            }
            writer.setOutput(out);
            writer.write(null, new IIOImage(image, null, null), param);
        } finally {
            writer.dispose();
        }
    }

    private static void pngEncoder(BufferedImage image, Path file, int level, boolean mt, boolean predictor)
            throws IOException {
        try (OutputStream out = Files.newOutputStream(file)) {
            new PngEncoder().withBufferedImage(image).withCompressionLevel(level)
                    .withMultiThreadedCompressionEnabled(mt).withPredictorEncoding(predictor).toStream(out);
        } catch (UncheckedIOException e) {
            throw e.getCause();
        }
    }

    private static void verify(BufferedImage expected, Path file, String name) throws IOException {
        BufferedImage back = ImageIO.read(file.toFile());
        int w = expected.getWidth();
        int h = expected.getHeight();
        int bands = expected.getRaster().getNumBands();
        boolean same = back.getWidth() == w && back.getHeight() == h && back.getRaster().getNumBands() == bands;
        int[] a = new int[w * bands];
        int[] b = new int[w * bands];
        for (int y = 0; same && y < h; y++) {
            if (bands == 1) {
                expected.getRaster().getSamples(0, y, w, 1, 0, a);
                back.getRaster().getSamples(0, y, w, 1, 0, b);
            } else {
                expected.getRGB(0, y, w, 1, a, 0, w);
                back.getRGB(0, y, w, 1, b, 0, w);
            }
            same = Arrays.equals(a, b);
        }
        if (!same) {
            throw new IllegalStateException(name + " did not round-trip: " + file);
        }
    }
}

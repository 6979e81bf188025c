#!/usr/bin/env python3
# Session 28 (docs/completion-record.md): does an image of the drawing around
# a strand-join candidate separate right from wrong candidates better than
# the committed join scorer (join_scorer.h)? Reads the folders that
# `train_join_scorer collect --crops DIR` fills (rows.csv, crops.u8), trains
#   cnn:    a small convolutional net on the crops alone,
#   fused:  the same trunk with the scorer's 44 inputs beside its pooled map,
#   mlp:    the scorer's architecture (44 -> 12 tanh -> 1) on the same rows,
# and reports on the evaluation folder, in the band the committed net decides
# (hand cost 2.4-4.0) and over all rows: AUC, and how many right candidates
# each accepts at the committed net's wrong ones (p >= 0.8). CPU, one thread.
# Needs python3-torch and python3-numpy (scripts/install-training-deps.sh).
import argparse
import math
import time

import numpy as np
import torch
import torch.nn as nn

CHANNELS = 8
FEATURES = 44


def load(folder, size):
    rows = [line.rstrip("\n").split(",") for line in open(folder + "/rows.csv")]
    crops = np.fromfile(folder + "/crops.u8", dtype=np.uint8)
    crops = crops.reshape(len(rows), CHANNELS, size, size)
    case = np.array([r[1] for r in rows])
    label = np.array([int(r[4]) for r in rows], dtype=np.int64)
    cost = np.array([float(r[5]) for r in rows])
    p_mlp = np.array([float(r[7]) for r in rows])
    feats = np.array([[float(v) for v in r[8:8 + FEATURES]] for r in rows], dtype=np.float32)
    return dict(case=case, label=label, cost=cost, p_mlp=p_mlp, feats=feats, crops=crops)


def subset(d, mask):
    return {k: v[mask] for k, v in d.items()}


class Net(nn.Module):
    def __init__(self, features):
        super().__init__()
        c = [CHANNELS, 16, 32, 64, 64]
        layers = []
        for k in range(4):
            layers += [nn.Conv2d(c[k], c[k + 1], 3, padding=1), nn.BatchNorm2d(c[k + 1]), nn.ReLU()]
            if k < 3:
                layers.append(nn.MaxPool2d(2))
        self.trunk = nn.Sequential(*layers, nn.AdaptiveAvgPool2d(1), nn.Flatten())
        self.features = features
        self.head = nn.Sequential(nn.Linear(64 + features, 32), nn.ReLU(), nn.Linear(32, 1))

    def forward(self, x, f=None):
        h = self.trunk(x)
        if self.features:
            h = torch.cat([h, f], 1)
        return self.head(h).squeeze(1)


class Mlp(nn.Module):
    # hidden=12, tanh: the committed net's shape; hidden=32, relu: the fused
    # net's head without the image (a control for its capacity).
    def __init__(self, hidden=12, act=nn.Tanh):
        super().__init__()
        self.net = nn.Sequential(nn.Linear(FEATURES, hidden), act(), nn.Linear(hidden, 1))

    def forward(self, x, f):
        # The crop adds nothing but stays an input, so that the exported
        # net has the fused one's inputs.
        return (self.net(f) + 0.0 * x[:, :1, :1, :1].flatten(1)).squeeze(1)


def augment(x, rng):
    # The crop's across direction is either way (flip rows); a and b are
    # either way round (flip columns and swap their masks).
    if rng.random() < 0.5:
        x = torch.flip(x, [2])
    if rng.random() < 0.5:
        x = torch.flip(x, [3])
        x = x[:, [0, 1, 2, 4, 3, 5, 6, 7]]
    return x


def auc(score, label):
    order = np.argsort(score, kind="mergesort")
    s = score[order]
    ranks = np.empty(len(s))
    i = 0
    while i < len(s):
        j = i
        while j < len(s) and s[j] == s[i]:
            j += 1
        ranks[i:j] = 0.5 * (i + j - 1) + 1
        i = j
    r = np.empty(len(s))
    r[order] = ranks
    pos = label.sum()
    neg = len(label) - pos
    if pos == 0 or neg == 0:
        return 0.5
    return (r[label == 1].sum() - pos * (pos + 1) / 2) / (pos * neg)


def predict(model, d, mean, std, batch=512):
    model.eval()
    out = []
    with torch.no_grad():
        for i in range(0, len(d["label"]), batch):
            x = torch.from_numpy(d["crops"][i:i + batch].astype(np.float32) / 255.0)
            f = torch.from_numpy((d["feats"][i:i + batch] - mean) / std)
            out.append(torch.sigmoid(model(x, f)).numpy())
    return np.concatenate(out) if out else np.zeros(0)


def train(model, tr, va, mean, std, epochs, rate, seed, name):
    rng = np.random.default_rng(seed)
    opt = torch.optim.Adam(model.parameters(), lr=rate, weight_decay=1e-4)
    pos = tr["label"].sum()
    neg = len(tr["label"]) - pos
    # Classes weighted to equal total weight, as the committed net's training.
    w = np.where(tr["label"] == 1, 0.5 / pos, 0.5 / neg) * len(tr["label"])
    best, best_state, best_epoch = -1.0, None, 0
    for epoch in range(epochs):
        model.train()
        t0 = time.time()
        order = rng.permutation(len(tr["label"]))
        total = 0.0
        for i in range(0, len(order), 64):
            idx = np.sort(order[i:i + 64])
            x = torch.from_numpy(tr["crops"][idx].astype(np.float32) / 255.0)
            x = augment(x, rng)
            f = torch.from_numpy((tr["feats"][idx] - mean) / std)
            y = torch.from_numpy(tr["label"][idx].astype(np.float32))
            wt = torch.from_numpy(w[idx].astype(np.float32))
            loss = (nn.functional.binary_cross_entropy_with_logits(model(x, f), y, reduction="none") * wt).mean()
            opt.zero_grad()
            loss.backward()
            opt.step()
            total += loss.item() * len(idx)
        p = predict(model, va, mean, std)
        band = (va["cost"] >= 2.4) & (va["cost"] <= 4.0)
        a_all, a_band = auc(p, va["label"]), auc(p[band], va["label"][band])
        print(f"{name} epoch {epoch + 1}: loss {total / len(order):.4f}, validation AUC all {a_all:.4f} "
              f"band {a_band:.4f} ({time.time() - t0:.0f} s)", flush=True)
        if a_band > best:
            best, best_epoch = a_band, epoch + 1
            best_state = {k: v.clone() for k, v in model.state_dict().items()}
    model.load_state_dict(best_state)
    print(f"{name}: kept epoch {best_epoch} (validation band AUC {best:.4f})", flush=True)
    return model


def report(title, d, scores, threshold=0.8):
    label = d["label"]
    pos = int(label.sum())
    mlp = d["p_mlp"]
    ref_tp = int(((mlp >= threshold) & (label == 1)).sum())
    ref_fp = int(((mlp >= threshold) & (label == 0)).sum())
    print(f"{title}: {len(label)} candidates ({pos} one strand); committed net at p >= {threshold}: "
          f"right / wrong {ref_tp} / {ref_fp}")
    for name, s in scores.items():
        # Right ones accepted at the committed net's wrong ones (at most).
        neg_scores = np.sort(s[label == 0])[::-1]
        t = neg_scores[ref_fp] if ref_fp < len(neg_scores) else -np.inf
        tp = int(((s > t) & (label == 1)).sum())
        fp = int(((s > t) & (label == 0)).sum())
        # Precision at the committed net's recall.
        k = max(ref_tp, 1)
        pos_scores = np.sort(s[label == 1])[::-1]
        cut = pos_scores[k - 1] if k <= len(pos_scores) else -np.inf
        fp_at = int(((s >= cut) & (label == 0)).sum())
        prec = k / (k + fp_at) if k + fp_at else 0.0
        print(f"  {name:10s} AUC {auc(s, label):.4f}; right / wrong at <= {ref_fp} wrong: {tp} / {fp}; "
              f"precision at recall {ref_tp / max(pos, 1):.3f}: {prec:.3f} ({k} / {k + fp_at})")


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--train", required=True, nargs="+", help="folders of rows.csv and crops.u8")
    ap.add_argument("--eval", required=True)
    ap.add_argument("--size", type=int, default=48)
    ap.add_argument("--epochs", type=int, default=12)
    ap.add_argument("--rate", type=float, default=2e-3)
    ap.add_argument("--window-low", type=float, default=1.0)
    ap.add_argument("--window-high", type=float, default=4.0)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--models", default="mlp,head,cnn,fused")
    ap.add_argument("--onnx", default="", help="write the fused (else cnn) net here")
    ap.add_argument("--save", default="", help="write eval scores (npz) here")
    args = ap.parse_args()
    torch.set_num_threads(1)
    torch.manual_seed(args.seed)

    parts = [load(f, args.size) for f in args.train]
    data = {k: np.concatenate([p[k] for p in parts]) for k in parts[0]}
    data = subset(data, (data["cost"] >= args.window_low) & (data["cost"] <= args.window_high))
    # A tenth of the training drawings picks the epoch; the evaluation rows never do.
    cases = np.unique(data["case"])
    held = set(np.random.default_rng(args.seed).choice(cases, len(cases) // 10, replace=False))
    is_va = np.array([c in held for c in data["case"]])
    tr, va = subset(data, ~is_va), subset(data, is_va)
    ev = load(args.eval, args.size)
    print(f"train {len(tr['label'])} rows ({tr['label'].sum()} one strand) of {len(cases) - len(held)} "
          f"drawings, validation {len(va['label'])}, evaluation {len(ev['label'])}")
    mean = tr["feats"].mean(0)
    std = tr["feats"].std(0) + 1e-6

    scores_ev = {"committed": ev["p_mlp"]}
    nets = {}
    for name in args.models.split(","):
        torch.manual_seed(args.seed)
        model = (Mlp() if name == "mlp" else Mlp(32, nn.ReLU) if name == "head"
                 else Net(FEATURES if name == "fused" else 0))
        t0 = time.time()
        epochs = 4 * args.epochs if name in ("mlp", "head") else args.epochs
        model = train(model, tr, va, mean, std, epochs, args.rate, args.seed, name)
        print(f"{name}: trained in {time.time() - t0:.0f} s", flush=True)
        t0 = time.time()
        scores_ev[name] = predict(model, ev, mean, std)
        dt = time.time() - t0
        print(f"{name}: {1e3 * dt / len(ev['label']):.2f} ms a candidate (batches of 512, one thread)")
        nets[name] = model
    if "cnn" in scores_ev:
        scores_ev["avg(cnn,committed)"] = 0.5 * (scores_ev["cnn"] + ev["p_mlp"])
    if "fused" in scores_ev:
        scores_ev["avg(fused,committed)"] = 0.5 * (scores_ev["fused"] + ev["p_mlp"])
    band = (ev["cost"] >= 2.4) & (ev["cost"] <= 4.0)
    kinds = np.array([c.split("-")[0] for c in ev["case"]])
    for title, m in [("band [2.4, 4.0]", band), ("all rows", np.ones_like(band))] + [
            (f"band, {k}", band & (kinds == k)) for k in ["flat", "two", "gradient", "screentone"]]:
        report(title, subset(ev, m), {k: v[m] for k, v in scores_ev.items()})
    # How sure: the band AUC's difference between two scorers over
    # bootstrap resamples of the evaluation drawings.
    pairs = [(a, b) for a, b in [("fused", "mlp"), ("fused", "head"), ("cnn", "committed")]
             if a in scores_ev and b in scores_ev]
    if pairs:
        rng = np.random.default_rng(0)
        cases = np.unique(ev["case"][band])
        by_case = {c: np.flatnonzero(band & (ev["case"] == c)) for c in cases}
        for a, b in pairs:
            diffs = []
            for _ in range(200):
                idx = np.concatenate([by_case[c] for c in rng.choice(cases, len(cases))])
                diffs.append(auc(scores_ev[a][idx], ev["label"][idx]) -
                             auc(scores_ev[b][idx], ev["label"][idx]))
            lo, hi = np.percentile(diffs, [2.5, 97.5])
            print(f"band AUC {a} - {b}: {np.mean(diffs):+.4f} (95 % of 200 resamples of the "
                  f"drawings in [{lo:+.4f}, {hi:+.4f}])")
    if args.save:
        np.savez(args.save, label=ev["label"], cost=ev["cost"], case=ev["case"], **{k.replace("(", "_").replace(",", "_").replace(")", ""): v for k, v in scores_ev.items()})
    if args.onnx:
        name = next(n for n in ["fused", "cnn", "head", "mlp"] if n in nets)
        model = nets[name].eval()
        x = torch.zeros(1, CHANNELS, args.size, args.size)
        f = torch.zeros(1, FEATURES)
        torch.onnx.export(model, (x, f), args.onnx, input_names=["crop", "features"],
                          output_names=["logit"], opset_version=11)
        # The features' standardisation, read by completion beside the net
        # (JoinScorerOptions::image_net): the means, then the deviations.
        with open(args.onnx + ".norm.txt", "w") as out:
            out.write(" ".join(f"{v:.9g}" for v in mean) + "\n")
            out.write(" ".join(f"{v:.9g}" for v in std) + "\n")
        print("wrote", args.onnx)


if __name__ == "__main__":
    main()
